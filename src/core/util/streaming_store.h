#pragma once
/// Stores that bypass the caches, for data written now and not read again
/// soon: a whole cache line is written without first being read from memory.
#include <cstring>
#include <type_traits>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace f2 {

/// `*to = from` for a value of whole 64-byte lines on a 64-byte boundary,
/// written around the caches where the CPU can. Call streamingStoreFence()
/// before another thread reads what was stored.
template <class T>
inline void streamingStore(T* to, const T& from) {
    static_assert(std::is_trivially_copyable_v<T> && sizeof(T) % 64 == 0 && alignof(T) % 64 == 0);
#if defined(__AVX512F__)
    for (std::size_t i = 0; i < sizeof(T); i += 64)
        _mm512_stream_si512(reinterpret_cast<__m512i*>(reinterpret_cast<char*>(to) + i),
                            _mm512_load_si512(reinterpret_cast<const char*>(&from) + i));
#elif defined(__SSE2__)
    for (std::size_t i = 0; i < sizeof(T); i += 16)
        _mm_stream_si128(
            reinterpret_cast<__m128i*>(reinterpret_cast<char*>(to) + i),
            _mm_load_si128(reinterpret_cast<const __m128i*>(reinterpret_cast<const char*>(&from) + i)));
#else
    std::memcpy(to, &from, sizeof(T));
#endif
}

/// Orders the streaming stores before every later store (a release by a lock
/// or an atomic then publishes them).
inline void streamingStoreFence() {
#if defined(__SSE2__)
    _mm_sfence();
#endif
}

}  // namespace f2
