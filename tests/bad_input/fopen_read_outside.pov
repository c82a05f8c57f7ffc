#fopen In "/etc/passwd" read
#read (In, Line)
