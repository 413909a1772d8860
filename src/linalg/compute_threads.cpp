#include "linalg/compute_threads.hpp"

#include <dlfcn.h>
#include <fmt/format.h>
#include <limits.h>
#include <omp.h>
#include <sched.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace tunica {

namespace {

/// OpenBLAS's run-time controls, if the BLAS in the process is OpenBLAS (looked up by name in the
/// process's global scope: libblas.so.3 may be OpenBLAS, ATLAS, BLIS or the reference BLAS).
struct OpenBlas {
  void (*set_num_threads)(int) = nullptr;
  int (*get_num_threads)() = nullptr;
  char* (*get_config)() = nullptr;
  int (*get_parallel)() = nullptr;  ///< 0 sequential, 1 pthreads, 2 OpenMP
};

const OpenBlas& openblas() {
  static const OpenBlas o = [] {
    OpenBlas r;
    r.set_num_threads = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    r.get_num_threads = reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
    r.get_config = reinterpret_cast<char* (*)()>(dlsym(RTLD_DEFAULT, "openblas_get_config"));
    r.get_parallel = reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "openblas_get_parallel"));
    return r;
  }();
  return o;
}

int threads_set = 0;  // 0: not set yet

}  // namespace

int default_compute_threads() {
  if (const char* env = std::getenv("OMP_NUM_THREADS")) {
    char* end = nullptr;
    const long n = std::strtol(env, &end, 10);  // "4", or the first level of a nested list "4,2"
    if (end != env && n >= 1 && n <= 4096 && (*end == '\0' || *end == ',')) return static_cast<int>(n);
  }
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0) {
    const int n = CPU_COUNT(&set);
    if (n >= 1) return n;
  }
  return 1;
}

void start_with_thread_environment(int n, char** argv) {
  if (n < 1) n = 1;
  const std::string count = std::to_string(n);
  // Started again already: the marker and the settings it stands for are all in place (a marker
  // left in the environment by a wrapper, without the settings, does not skip the start: OpenBLAS
  // would have started its pool when it loaded).
  const auto is = [](const char* name, const std::string& value) {
    const char* v = std::getenv(name);
    return v && value == v;
  };
  if (is("TUNICA_THREADS", count) && is("OMP_NUM_THREADS", count) && is("OMP_THREAD_LIMIT", count) &&
      is("OPENBLAS_NUM_THREADS", "1"))
    return;
  // Valgrind follows an exec only with --trace-children=yes: under it the run goes on as started,
  // or valgrind would watch nothing of it.
  if (const char* preload = std::getenv("LD_PRELOAD"); preload && std::strstr(preload, "vgpreload")) return;
  setenv("OMP_NUM_THREADS", count.c_str(), 1);
  // A cap on every OpenMP team in the process, a library's num_threads clause included.
  setenv("OMP_THREAD_LIMIT", count.c_str(), 1);
  // The BLAS on the calling thread: OpenBLAS then starts no pool when it loads.
  setenv("OPENBLAS_NUM_THREADS", "1", 1);
  setenv("BLIS_NUM_THREADS", "1", 1);
  setenv("MKL_NUM_THREADS", "1", 1);
  // An element loop's workers sleep as soon as the loop ends, rather than spin while the
  // factorization runs: spinning workers take the cores that the factorization and other
  // processes need, and a team whose thread lost its core waits for it at every colour.
  if (!std::getenv("OMP_WAIT_POLICY") && !std::getenv("GOMP_SPINCOUNT")) setenv("OMP_WAIT_POLICY", "passive", 1);
  setenv("TUNICA_THREADS", count.c_str(), 1);
  char self[PATH_MAX];
  const ssize_t length = readlink("/proc/self/exe", self, sizeof self - 1);
  if (length > 0) {
    self[length] = '\0';
    execv(self, argv);
  }
  std::fprintf(stderr,
               "tunica: warning: could not start again with the thread settings in the environment (%s): "
               "the element loops' idle threads spin as libgomp's default has them\n",
               std::strerror(length > 0 ? errno : ENOENT));
}

void set_compute_threads(int n) {
  if (n < 1) n = 1;
  omp_set_dynamic(0);
  omp_set_num_threads(n);
  if (openblas().set_num_threads) openblas().set_num_threads(1);
  threads_set = n;
}

int compute_threads() { return threads_set > 0 ? threads_set : omp_get_max_threads(); }

int blas_threads() { return openblas().get_num_threads ? openblas().get_num_threads() : 0; }

std::string compute_threads_summary() {
  std::string blas = "BLAS (not OpenBLAS: BLIS_NUM_THREADS, MKL_NUM_THREADS) 1";
  if (openblas().get_num_threads) {
    std::string config = openblas().get_config ? openblas().get_config() : "OpenBLAS";
    config = config.substr(0, config.find(' ', config.find(' ') + 1));  // "OpenBLAS 0.3.21"
    const int parallel = openblas().get_parallel ? openblas().get_parallel() : -1;
    const char* kind = parallel == 0 ? " sequential" : parallel == 1 ? " pthreads" : parallel == 2 ? " OpenMP" : "";
    blas = fmt::format("BLAS ({}{}) {}", config, kind, blas_threads());
  }
  const char* wait = std::getenv("OMP_WAIT_POLICY");
  const char* spin = std::getenv("GOMP_SPINCOUNT");
  const std::string waits = wait ? fmt::format("idle threads wait {}", wait)
                            : spin ? fmt::format("idle threads spin GOMP_SPINCOUNT={}", spin)
                                   : std::string("idle threads spin first (libgomp's default)");
  return fmt::format("{} (element loops {}; {} and CHOLMOD's loops 1, so that results do not depend on the count; {})",
                     compute_threads(), omp_get_max_threads(), blas, waits);
}

SerialOpenMP::SerialOpenMP() : saved_(omp_get_max_active_levels()) { omp_set_max_active_levels(0); }

SerialOpenMP::~SerialOpenMP() { omp_set_max_active_levels(saved_); }

}  // namespace tunica
