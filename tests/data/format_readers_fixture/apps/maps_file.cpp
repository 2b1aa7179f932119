#include <sys/mman.h>
const void* map(int descriptor, unsigned long size) {
  return mmap(nullptr, size, PROT_READ, MAP_PRIVATE, descriptor, 0);
}
