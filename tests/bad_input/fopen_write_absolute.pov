#fopen Out "/tmp/wardray_escape_abs.txt" write
#write (Out, "escaped\n")
#fclose Out
