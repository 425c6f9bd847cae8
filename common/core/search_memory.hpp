#pragma once
// Memory for the arrays a search reads in no order (a wide BVH's nodes, a mesh's triangle
// blocks and corners). A ray's walk touches a few lines here and there across megabytes,
// so with 4 KiB pages nearly every visit on a big mesh also needs a page translation the
// TLB does not hold. An array of 2 MiB or more is therefore placed on a 2 MiB boundary and
// the kernel asked to back it with huge pages (madvise, which Linux's default "madvise"
// setting for transparent huge pages honours); book §C.2 and §C.3 record what that gained on the
// dragon. Smaller arrays, and systems that decline, get ordinary memory: only speed depends
// on it.
#include <sys/mman.h>

#include <cstddef>
#include <cstdlib>
#include <new>

namespace rt {

inline constexpr std::size_t kHugePage = std::size_t(2) << 20;

inline void* allocate_search_memory(std::size_t bytes, std::size_t alignment) {
    if (bytes < kHugePage) return ::operator new(bytes, std::align_val_t(alignment));
    const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
    void* p = std::aligned_alloc(kHugePage, rounded);
    if (p == nullptr) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
    madvise(p, rounded, MADV_HUGEPAGE);  // advice only: a refusal changes nothing but speed
#endif
    return p;
}

inline void free_search_memory(void* p, std::size_t bytes, std::size_t alignment) {
    if (bytes < kHugePage)
        ::operator delete(p, std::align_val_t(alignment));
    else
        std::free(p);
}

template <class T>
struct SearchAllocator {
    using value_type = T;

    SearchAllocator() = default;
    template <class U>
    SearchAllocator(const SearchAllocator<U>&) {}

    T* allocate(std::size_t n) { return static_cast<T*>(allocate_search_memory(n * sizeof(T), alignof(T))); }
    void deallocate(T* p, std::size_t n) { free_search_memory(p, n * sizeof(T), alignof(T)); }

    template <class U>
    bool operator==(const SearchAllocator<U>&) const {
        return true;
    }
};

}  // namespace rt
