// Process-wide allocator settings for the dense solver.
//
// Every RFM solve allocates and frees dense matrices of 1-100 MiB (basis values at the
// quadrature points, the blocks of the saddle-point system, the Schur complement). glibc
// serves blocks above its mmap threshold (128 KiB at start) with fresh mmap'd pages and
// returns them on free, so every solve pays the page faults of its whole working set again:
// measured on the project's 2-core machine, half the wall time of a contact search was
// kernel time (2.24 s wall, 1.09 s sys for the default die problem; 0.35 s wall with the
// settings below, same results bit for bit). Keeping freed blocks in the heap removes it.
#pragma once

namespace rfm
{
  /// Raises glibc's mmap threshold to its maximum (32 MiB) and the trim threshold to
  /// 1 GiB, so that freed matrices are reused by the next solve instead of unmapped. Call
  /// once at the start of main; a no-op on other C libraries.
  void keep_freed_matrices_in_heap();
} // namespace rfm
