// Per-thread caches of the numeric libraries, released before a thread ends.
#pragma once

namespace gyrores {

// Frees the calling thread's MPFR and Arb/FLINT caches (constants such as pi, sine tables). A
// thread that used MPFR or Arb must call it before it ends (MPFR's manual, mpfr_free_cache;
// FLINT's flint_cleanup), or those caches leak: the sweep's workers do (src/lib/sweep/engine.cpp).
// Defined in src/lib/core/real_sin_cos.cpp, the file that includes Arb.
void release_thread_caches();

}  // namespace gyrores
