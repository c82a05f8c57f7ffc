#macro Two(A, B) sphere { A, B } #end
Two(<0, 0, 0>)
