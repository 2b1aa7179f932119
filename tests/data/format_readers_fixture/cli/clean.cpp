// Names that look like reads and are not: a comment about std::ifstream, fopen(, getline( and mmap(,
// member functions named open and read, a stream that only writes, and the header <fstream>.
#include <fstream>
#include "storage/atomic_file.hpp"
struct Port {
  bool read(double time_s, int& sample);
  void open(double sample_rate_hz);
};
void use(Port& port, Port* other, int& sample) {
  port.open(8000.0);
  other->read(0.0, sample);  // not ::read(fd, ...)
  std::ofstream out("log.txt");
  out << "fopen( and getline( in a string are not calls\n" ? 0 : 1;
  const int fd_count = 2;
  (void)fd_count;
}
