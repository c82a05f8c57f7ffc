union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
union {
sphere { 0, 1 }
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
}
