// paper_figures/driver/thread_heap.cpp — the driver's operator new and delete, counting each
// thread's bytes (thread_heap.hpp). Every block is freed by the thread that allocated it in
// the tables that read the count; a block freed by another thread moves that thread's count.
#include "driver/thread_heap.hpp"

#include <cstdlib>
#include <new>

#if defined(__GLIBC__)
#include <malloc.h>
#define FIGURES_COUNT_HEAP 1
#endif

namespace {
#ifdef FIGURES_COUNT_HEAP
thread_local long t_heap_bytes = 0;
// A block as glibc's malloc holds it: the usable bytes and the one-word size header in front
// (what mallinfo2's uordblks sums; a block of 24 usable bytes is a 32-byte chunk).
long block_bytes(void* p) { return long(malloc_usable_size(p) + sizeof(std::size_t)); }
#endif

void* allocate(std::size_t size) {
    void* p = std::malloc(size == 0 ? 1 : size);
    if (p == nullptr) throw std::bad_alloc();
#ifdef FIGURES_COUNT_HEAP
    t_heap_bytes += block_bytes(p);
#endif
    return p;
}

void release(void* p) noexcept {
    if (p == nullptr) return;
#ifdef FIGURES_COUNT_HEAP
    t_heap_bytes -= block_bytes(p);
#endif
    std::free(p);
}
}  // namespace

namespace shitsukan::figures {

long thread_heap_bytes() {
#ifdef FIGURES_COUNT_HEAP
    return t_heap_bytes;
#else
    return -1;
#endif
}

}  // namespace shitsukan::figures

// The replaceable forms without alignment (the aligned ones keep the library's, uncounted).
void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    try {
        return allocate(size);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    try {
        return allocate(size);
    } catch (...) {
        return nullptr;
    }
}
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { release(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { release(p); }
