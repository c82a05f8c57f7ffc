#declare Ã©tÃ© = 1;
sphere { 0, ÿş }
