#include <fcntl.h>
#include <unistd.h>
void load(const char* path, char* bytes) {
  int fd = ::open(path, O_RDONLY);
  ::read(fd, bytes, 16);
  const int data_fd = open(path, O_RDONLY | O_CLOEXEC);
  long n = read(data_fd, bytes, 16);
  n += pread(fd, bytes, 16, 0);
}
