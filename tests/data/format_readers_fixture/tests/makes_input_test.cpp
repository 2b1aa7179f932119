#include <cstdio>
void make(const char* path) { FILE* f = std::fopen(path, "rb"); (void)f; }
