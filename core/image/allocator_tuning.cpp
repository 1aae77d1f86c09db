#include "core/image/allocator_tuning.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace rayo {

void tune_allocator_for_image_writing() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 4 << 20);
    mallopt(M_TRIM_THRESHOLD, 16 << 20);
#endif
}

}  // namespace rayo
