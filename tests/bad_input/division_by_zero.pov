#declare Zero = 0;
#declare X = 1 / Zero;
sphere { 0, X }
