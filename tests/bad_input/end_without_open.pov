#end
