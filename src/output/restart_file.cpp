#include "output/restart_file.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "core/bounded_file.hpp"

namespace tunica {

namespace {

constexpr const char* kMagic = "tunica-restart 8";
constexpr const char* kMagicWithoutSmoothing = "tunica-restart 7";
constexpr const char* kMagicWithoutPrestress = "tunica-restart 6";
constexpr const char* kMagicWithoutReference = "tunica-restart 5";
constexpr const char* kMagicWithoutTrace = "tunica-restart 4";
constexpr const char* kMagicWithoutFingerprint = "tunica-restart 3";
constexpr long kMaxFingerprint = 1'000'000;
constexpr std::size_t kMaxFingerprintText = 4096;  // bytes of one key or value

std::string hex(const std::string& text) {
  std::string h;
  for (unsigned char c : text) h += fmt::format("{:02x}", c);
  return h.empty() ? "-" : h;
}
constexpr long kMaxFiles = 16;
constexpr long kMaxValues = 100'000'000;  // refuse absurd counts before allocating

void put(std::string& s, const char* key, const std::vector<double>& v) {
  s += fmt::format("{} {}", key, v.size());
  for (double x : v) s += fmt::format(" {:a}", x);
  s += "\n";
}

class Reader {
public:
  Reader(const std::string& path, const std::string& text) : path_(path), in_(text) {}
  /// Next line, which must start with `key`; returns the rest split in words.
  std::vector<std::string> line(const std::string& key) {
    std::string l;
    if (!std::getline(in_, l)) fail("ends early: expected '" + key + "'");
    ++line_;
    std::istringstream ss(l);
    std::string k;
    ss >> k;
    if (k != key) fail("expected '" + key + "', got '" + k + "'");
    std::vector<std::string> words;
    for (std::string w; ss >> w;) words.push_back(w);
    return words;
  }
  double number(const std::string& w) {
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(w.c_str(), &end);
    if (w.empty() || *end || errno == ERANGE) fail("not a number: '" + w + "'");
    return v;
  }
  long integer(const std::string& w, long max) {
    char* end = nullptr;
    errno = 0;
    const long v = std::strtol(w.c_str(), &end, 10);
    if (w.empty() || *end || errno == ERANGE || v < 0 || v > max) fail("not a count in [0, " + std::to_string(max) + "]: '" + w + "'");
    return v;
  }
  long scalar_int(const std::string& key, long max) {
    auto w = line(key);
    if (w.size() != 1) fail("'" + key + "' takes one value");
    return integer(w[0], max);
  }
  double scalar(const std::string& key) {
    auto w = line(key);
    if (w.size() != 1) fail("'" + key + "' takes one value");
    return number(w[0]);
  }
  std::vector<double> vector(const std::string& key) {
    auto w = line(key);
    if (w.empty()) fail("'" + key + "' needs a count");
    const long n = integer(w[0], kMaxValues);
    if (static_cast<long>(w.size()) != n + 1) fail(fmt::format("'{}' announces {} values and holds {}", key, n, w.size() - 1));
    std::vector<double> v;
    v.reserve(n);
    for (long i = 1; i <= n; ++i) v.push_back(number(w[i]));
    return v;
  }
  std::uint32_t hex32(const std::string& w) {
    char* end = nullptr;
    errno = 0;
    const unsigned long v = std::strtoul(w.c_str(), &end, 16);
    if (w.size() != 8 || *end || errno == ERANGE || v > 0xffffffffUL) fail("not a CRC-32 (8 hex digits): '" + w + "'");
    return static_cast<std::uint32_t>(v);
  }
  /// The text `hex()` wrote.
  std::string unhex(const std::string& w) {
    if (w == "-") return "";
    if (w.size() % 2 || w.size() > 2 * kMaxFingerprintText) fail("not a hex-encoded text: '" + w.substr(0, 40) + "'");
    std::string t;
    for (std::size_t i = 0; i < w.size(); i += 2) {
      const auto digit = [&](char c) -> int {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        fail("not a hex-encoded text: '" + w.substr(0, 40) + "'");
      };
      t += static_cast<char>(digit(w[i]) * 16 + digit(w[i + 1]));
    }
    return t;
  }
  /// Bytes read so far (the start of the next line).
  std::size_t position() { return static_cast<std::size_t>(in_.tellg()); }
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError({path_, line_, 0, ""}, "malformed restart file: " + what);
  }

private:
  std::string path_;
  std::istringstream in_;
  int line_ = 0;
};

}  // namespace

std::string restart_text(const RestartRecord& r) {
  const Checkpoint& c = r.checkpoint;
  std::string s = std::string(kMagic) + "\n";
  s += "deck " + r.deck + "\n";
  s += fmt::format("step {}\nfraction {:a}\ndt {:a}\nincrement {}\nreduced_successes {}\n", c.step, c.fraction, c.dt,
                   c.increment, c.reduced_successes);
  s += fmt::format("history_rows {}\nnewton_rows {}\nframes {}\nfiles {}\n", r.history_rows, r.newton_rows, r.frames,
                   r.files.size());
  for (const auto& f : r.files) s += fmt::format("file {} {} {:08x}\n", f.name, f.size_bytes, f.crc32);
  s += fmt::format("fingerprint {}\n", r.fingerprint.size());
  for (const auto& e : r.fingerprint) s += fmt::format("key {} {} {}\n", e.step + 1, hex(e.key), hex(e.value));
  put(s, "step_start_boundary", c.step_start.boundary);
  put(s, "step_start_pressure", c.step_start.pressure);
  put(s, "step_start_volume", c.step_start.volume);
  put(s, "boundary", c.loads.boundary);
  put(s, "pressure", c.loads.pressure);
  put(s, "volume", c.loads.volume);
  // The step's converged states the hints of a failure read (solver/step_trace.hpp): their
  // pressures and volumes, state after state.
  std::vector<double> trace_pressure, trace_volume;
  for (const LoadState& t : c.trace.kept()) {
    trace_pressure.insert(trace_pressure.end(), t.pressure.begin(), t.pressure.end());
    trace_volume.insert(trace_volume.end(), t.volume.begin(), t.volume.end());
  }
  s += fmt::format("trace {} {}\n", c.trace.count(), c.trace.kept().size());
  put(s, "trace_pressure", trace_pressure);
  put(s, "trace_volume", trace_volume);
  put(s, "u", std::vector<double>(c.u.data(), c.u.data() + c.u.size()));
  // After an inverse step, the reference it computed, as its shift from the deck's positions.
  put(s, "reference_shift",
      std::vector<double>(c.reference_shift.data(), c.reference_shift.data() + c.reference_shift.size()));
  // After a prestress step, its prestretch and stress-free thickness per Gauss point.
  put(s, "prestress", c.prestress);
  // The contact smoothing the run switched on by itself, per pair (theory manual (9.2)).
  put(s, "contact_smoothing", c.contact_smoothing);
  return s + fmt::format("checksum {:08x}\n", crc32_of(s));
}

RestartRecord read_restart(const std::string& path) {
  const std::string text = read_file_bounded(path, kMaxRestartBytes, "restart file");
  Reader in(path, text);
  RestartRecord r;
  bool has_trace = false, has_reference = false, has_prestress = false, has_smoothing = false;
  {
    const std::string first = text.substr(0, text.find('\n'));
    r.has_fingerprint = first != kMagicWithoutFingerprint;
    has_smoothing = first == kMagic;
    has_prestress = has_smoothing || first == kMagicWithoutSmoothing;
    has_reference = has_prestress || first == kMagicWithoutPrestress;
    has_trace = has_reference || first == kMagicWithoutReference;
    if (first.rfind("tunica-restart ", 0) == 0 && first != kMagic && first != kMagicWithoutSmoothing &&
        first != kMagicWithoutPrestress &&
        first != kMagicWithoutReference && first != kMagicWithoutTrace && r.has_fingerprint)
      in.fail("written by another version of Tunica ('" + first.substr(0, 40) + "'; this one reads '" + kMagic +
              "', '" + kMagicWithoutSmoothing + "', '" + kMagicWithoutPrestress + "', '" + kMagicWithoutReference + "', '" + kMagicWithoutTrace +
              "' and '" + kMagicWithoutFingerprint + "')");
    if (first.rfind("tunica-restart ", 0) != 0) in.fail("not a Tunica restart file (first line '" + first.substr(0, 40) + "')");
  }
  in.line("tunica-restart");
  const auto deck = in.line("deck");
  for (const auto& w : deck) r.deck += (r.deck.empty() ? "" : " ") + w;
  Checkpoint& c = r.checkpoint;
  c.step = static_cast<int>(in.scalar_int("step", 1'000'000));
  c.fraction = in.scalar("fraction");
  c.dt = in.scalar("dt");
  c.increment = static_cast<int>(in.scalar_int("increment", 1'000'000'000));
  c.reduced_successes = static_cast<int>(in.scalar_int("reduced_successes", 1'000'000'000));
  r.history_rows = static_cast<int>(in.scalar_int("history_rows", 1'000'000'000));
  r.newton_rows = static_cast<int>(in.scalar_int("newton_rows", 1'000'000'000));
  r.frames = in.scalar_int("frames", kMaxValues);
  const long files = in.scalar_int("files", kMaxFiles);
  for (long k = 0; k < files; ++k) {
    const auto w = in.line("file");
    if (w.size() != 3) in.fail("'file' takes a name, a byte length and a CRC-32");
    if (w[0].empty() || w[0].find("..") != std::string::npos || w[0][0] == '/') in.fail("not a file of the run: '" + w[0] + "'");
    r.files.push_back({w[0], static_cast<std::uint64_t>(in.integer(w[1], 1L << 50)), in.hex32(w[2])});
  }
  if (r.has_fingerprint) {
    const long entries = in.scalar_int("fingerprint", kMaxFingerprint);
    for (long k = 0; k < entries; ++k) {
      const auto w = in.line("key");
      if (w.size() != 3) in.fail("'key' takes a step, a key and a value");
      r.fingerprint.push_back({in.unhex(w[1]), in.unhex(w[2]), static_cast<int>(in.integer(w[0], 1'000'000)) - 1});
    }
  }
  c.step_start.boundary = in.vector("step_start_boundary");
  c.step_start.pressure = in.vector("step_start_pressure");
  c.step_start.volume = in.vector("step_start_volume");
  c.loads.boundary = in.vector("boundary");
  c.loads.pressure = in.vector("pressure");
  c.loads.volume = in.vector("volume");
  if (has_trace) {
    const auto w = in.line("trace");
    if (w.size() != 2) in.fail("'trace' takes a count of states and the number kept");
    const long count = in.integer(w[0], 1'000'000'000);
    const long kept = in.integer(w[1], static_cast<long>(StepTrace::kFirst + StepTrace::kLast));
    const auto pressure = in.vector("trace_pressure");
    const auto volume = in.vector("trace_volume");
    const std::size_t loads = c.loads.pressure.size();
    if (pressure.size() != kept * loads || volume.size() != kept * loads)
      in.fail(fmt::format("the trace holds {} pressures and {} volumes for {} states of {} loads", pressure.size(),
                          volume.size(), kept, loads));
    std::vector<LoadState> states(kept);
    for (long k = 0; k < kept; ++k) {
      states[k].pressure.assign(pressure.begin() + k * loads, pressure.begin() + (k + 1) * loads);
      states[k].volume.assign(volume.begin() + k * loads, volume.begin() + (k + 1) * loads);
      states[k].step = c.step;
    }
    try {
      c.trace = StepTrace::recorded(std::move(states), count);
    } catch (const std::invalid_argument& e) {
      in.fail(e.what());
    }
  }
  const auto u = in.vector("u");
  c.u = Eigen::Map<const Eigen::VectorXd>(u.data(), static_cast<Eigen::Index>(u.size()));
  if (has_reference) {
    const auto shift = in.vector("reference_shift");
    c.reference_shift = Eigen::Map<const Eigen::VectorXd>(shift.data(), static_cast<Eigen::Index>(shift.size()));
  }
  if (has_prestress) {
    c.prestress = in.vector("prestress");
    if (c.prestress.size() % 5 != 0) in.fail("'prestress' takes 5 values per Gauss point");
  }
  if (has_smoothing) {
    c.contact_smoothing = in.vector("contact_smoothing");
    for (double d : c.contact_smoothing)
      if (!(d >= 0) || !std::isfinite(d)) in.fail("'contact_smoothing' takes widths ≥ 0");
  }
  if (!(c.fraction >= 0 && c.fraction <= 1) || !(c.dt >= 0 && c.dt <= 1)) in.fail("step fraction out of [0, 1]");
  // Last: the CRC-32 of every byte before this line. A restart file edited by hand or damaged
  // in a way that still parses is refused here.
  const std::size_t signed_bytes = in.position();
  const auto sum = in.line("checksum");
  if (sum.size() != 1) in.fail("'checksum' takes one value");
  const std::uint32_t recorded = in.hex32(sum[0]);
  if (crc32_of(text.substr(0, signed_bytes)) != recorded)
    throw InputError({path, 0, 0, ""}, "the restart file was changed after Tunica wrote it (its CRC-32 does not match "
                                       "its recorded checksum): refusing to continue from it");
  return r;
}

}  // namespace tunica
