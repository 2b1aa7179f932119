#include <fstream>
void load(const char* path) {
  std::ifstream in(path);
  std::fstream both(path);
  std::basic_filebuf<char> raw;
}
