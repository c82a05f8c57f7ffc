#declare Grid = array[100000][100000][100];
