#include <istream>
#include <string>
void lines(std::istream& in) {
  std::string line;
  while (std::getline(in, line)) {
  }
  char buffer[64];
  in.getline(buffer, sizeof buffer);
}
