#include <fcntl.h>
#include <fstream>
int bus(const char* node) { return ::open(node, O_RDWR | O_CLOEXEC); }
void calibration(const char* path) { std::ifstream in(path); }
