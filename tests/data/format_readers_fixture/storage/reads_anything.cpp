#include <cstdio>
#include <fstream>
void load(const char* path) { std::ifstream in(path); FILE* f = std::fopen(path, "rb"); (void)f; }
