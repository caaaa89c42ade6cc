/* Must not link: firmware images have no heap (see CMakeLists.txt, HSTMON_NO_HEAP_WRAP). */
#include <stdlib.h>

int main(void) {
  void* p = malloc(16);
  return p != NULL;
}
