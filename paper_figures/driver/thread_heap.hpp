// paper_figures/driver/thread_heap.hpp — the heap bytes the calling thread holds through
// operator new, for tables that check a container's own byte count against the allocator.
//
//   const long before = shitsukan::figures::thread_heap_bytes();
//   std::vector<int> v(1000);
//   const long grown = shitsukan::figures::thread_heap_bytes() - before;  // >= 4000 where counted
//
// The driver runs figures on several threads at once, so a process-wide figure (glibc's
// mallinfo2) moves with the other jobs' allocations; this counts only what the calling thread
// allocates minus what it frees, in glibc's block sizes (malloc_usable_size plus the block's
// one-word header). -1 where the C library cannot tell a block's size.
#pragma once

namespace shitsukan::figures {

long thread_heap_bytes();

}  // namespace shitsukan::figures
