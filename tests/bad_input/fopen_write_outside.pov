#fopen Out "../../../../../../tmp/wardray_escape.txt" write
#write (Out, "escaped\n")
#fclose Out
