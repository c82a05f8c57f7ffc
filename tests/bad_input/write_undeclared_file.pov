#write (Nowhere, "text")
