#macro Ping(N) Pong(N) #end
#macro Pong(N) Ping(N) #end
Ping(1)
