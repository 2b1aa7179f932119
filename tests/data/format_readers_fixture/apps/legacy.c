#include <stdio.h>
int first_byte(const char* path) { FILE* f = fopen(path, "rb"); return fgetc(f); }
