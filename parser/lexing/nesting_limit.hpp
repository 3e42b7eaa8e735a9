// How deep the parse may nest: input nested deeper than kMaxNesting levels (parentheses, vectors, unary operators,
// object { object { … } }, transform blocks) is refused with an error instead of overflowing the C++ stack —
// POV-Ray itself crashes there. The reader's NestingGuard counts the levels; the expression programs, which pass
// levels by without the guard, ask the same limits (expression_programs.hpp).
#pragma once

#include <cstddef>

#include <pthread.h>

namespace povtrace::sdl {

inline constexpr int kMaxNesting = 500;

// The lowest address of the calling thread's stack (null where it cannot be known). Found once per thread:
// for the main thread glibc reads /proc/self/maps.
inline const char* stack_lowest_address() {
#if defined(__GLIBC__)
  thread_local const char* lowest = [] {
    pthread_attr_t attr;
    if (pthread_getattr_np(pthread_self(), &attr) != 0) return static_cast<const char*>(nullptr);
    void* address = nullptr;
    std::size_t size = 0;
    const bool ok = pthread_attr_getstack(&attr, &address, &size) == 0;
    pthread_attr_destroy(&attr);
    return ok ? static_cast<const char*>(address) : nullptr;
  }();
  return lowest;
#else
  return nullptr;
#endif
}

// Stack kept free below the deepest nesting level: what runs between two levels, the error message and the
// unwinding of the exception.
inline constexpr std::ptrdiff_t kStackReserve = 256 * 1024;

// Whether the stack below `here` (a frame address of the caller) keeps kStackReserve free.
inline bool stack_room_below(const char* here) {
  const char* lowest = stack_lowest_address();
  return !(lowest && here - lowest < kStackReserve);
}

}  // namespace povtrace::sdl
