#pragma once
// The threads of the process's compute teams, all governed by one count N (`tunica run -j N`), so
// that the process never computes on more than N threads:
//   - Tunica's element loops (OpenMP, libgomp): N threads. Their results do not depend on N (the
//     loops are coloured: contributions/element_loop.hpp).
//   - The BLAS under CHOLMOD and UMFPACK (the libblas.so.3 alternative; OpenBLAS keeps a pthread
//     pool of its own): 1 thread whatever N. OpenBLAS splits a factorization's dense kernels
//     differently with more threads, which changes the last bits of the solution, and results
//     must not depend on N.
//   - CHOLMOD's own OpenMP loops: 1 thread. Debian's CHOLMOD 5.12 asks for num_threads(4) (a
//     clause that omp_set_num_threads does not cap) on the loops that clear and scatter a
//     supernode, a team per supernode; these memory-bound loops run on the calling thread
//     (SerialOpenMP).
// libgomp reads its thread limit and wait policy, and OpenBLAS the size of its pool, from the
// environment when the process loads them, before main: start_with_thread_environment sets them
// and executes the program again.
#include <string>

namespace tunica {

/// The threads the process may use when the user says nothing: OMP_NUM_THREADS if it is set (its
/// first value), else the CPUs of the process's affinity mask (sched_getaffinity: a taskset or a
/// container's cpuset), at least 1.
int default_compute_threads();

/// Unless the environment already holds the thread settings for n threads (TUNICA_THREADS=n, set
/// here), sets OMP_NUM_THREADS and OMP_THREAD_LIMIT to n, the BLAS's threads (OPENBLAS_NUM_THREADS,
/// BLIS_NUM_THREADS, MKL_NUM_THREADS) to 1 and OMP_WAIT_POLICY to passive (unless the user set it
/// or GOMP_SPINCOUNT), and executes this program again with the same arguments (same process id).
/// Returns when that is not needed, under valgrind (which would not follow the exec), or when the
/// exec fails (with a warning on stderr); then set_compute_threads still sets the counts, and the
/// waits are the libraries' defaults.
void start_with_thread_environment(int n, char** argv);

/// Sets the teams for n threads (n ≥ 1): OpenMP's element loops to n (omp_set_num_threads,
/// dynamic adjustment off) and OpenBLAS's pool, if the BLAS is OpenBLAS, to 1.
void set_compute_threads(int n);

/// The count set by set_compute_threads; before any call, the element loops' (omp_get_max_threads).
int compute_threads();

/// One line for a run's header: the count and each team's threads, e.g. "2 (element loops 2;
/// BLAS (OpenBLAS 0.3.21 pthreads) 1 and CHOLMOD's loops 1, so that results do not depend on the
/// count; idle threads wait passive)".
std::string compute_threads_summary();

/// The threads OpenBLAS's calls use now (openblas_get_num_threads), or 0 when the BLAS is not
/// OpenBLAS.
int blas_threads();

/// While it lives, every OpenMP parallel region started by the calling thread runs on that thread
/// alone (max-active-levels 0): for the calls into CHOLMOD, whose num_threads(4) loops would
/// otherwise start a team of 4 whatever the thread count.
class SerialOpenMP {
public:
  SerialOpenMP();
  ~SerialOpenMP();
  SerialOpenMP(const SerialOpenMP&) = delete;
  SerialOpenMP& operator=(const SerialOpenMP&) = delete;

private:
  int saved_;
};

}  // namespace tunica
