#include "core/suggest.hpp"

#include <algorithm>
#include <cctype>
#include <utility>

#include "core/printable.hpp"

namespace tunica {

namespace {

/// Optimal string alignment distance (Levenshtein with transpositions of neighbours).
std::size_t edit_distance(std::string_view a, std::string_view b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

namespace {

std::string digits_of(const std::string& s) {
  std::string d;
  for (char c : s)
    if (std::isdigit(static_cast<unsigned char>(c))) d += c;
  return d;
}

/// How far `name` is from `known` (both lower case), if `known` is near enough to be its typo;
/// -1 if not. Names that share a prefix up to a dot (`wall.x0`, `wall.y0`: the sets of one part)
/// are compared by what follows it, as file names are by their stems: at most one edit for 3 to
/// 6 characters, two from 7 on, none below 3, and the same digits (`x0` and `y0`, `ring1` and
/// `ring2` are other sets, not typos). Others by the whole name: at most 1 edit for names of up to
/// 5 characters, 2 for longer ones, and fewer edits than the name has characters.
long typo_distance(const std::string& name, const std::string& known) {
  if (name == known) return 0;
  const std::size_t dot = name.rfind('.');
  if (dot != std::string::npos && dot + 1 < name.size() && known.size() > dot && known.compare(0, dot + 1, name, 0, dot + 1) == 0 &&
      known.find('.', dot + 1) == std::string::npos) {
    const std::string a = name.substr(dot + 1), b = known.substr(dot + 1);
    const std::size_t allowed = a.size() < 3 ? 0 : a.size() < 7 ? 1 : 2;
    const std::size_t d = edit_distance(a, b);
    return d <= allowed && digits_of(a) == digits_of(b) ? static_cast<long>(d) : -1;
  }
  const std::size_t d = edit_distance(name, known);
  const std::size_t allowed = name.size() <= 5 ? 1 : 2;
  return d <= allowed && d < name.size() ? static_cast<long>(d) : -1;
}

}  // namespace

std::string nearest_name(std::string_view name, const std::vector<std::string>& known) {
  constexpr std::size_t kLongest = 200;  // names longer than this are not compared (a bound on the work)
  if (name.empty() || name.size() > kLongest) return "";
  const std::string low = lower(name);
  std::string best;
  long best_d = -1;
  for (const auto& k : known) {
    if (k == name || k.size() > kLongest) continue;
    const long d = typo_distance(low, lower(k));
    if (d >= 0 && (best_d < 0 || d < best_d)) best = k, best_d = d;
  }
  if (!best.empty() || low.find('.') != std::string::npos) return best;
  // A name without its prefix (`start` for a part's `wall.start`): the one known name that ends in
  // it after a dot, if only one does.
  int count = 0;
  for (const auto& k : known) {
    const std::string lk = lower(k);
    if (lk.size() > low.size() + 1 && lk.compare(lk.size() - low.size(), low.size(), low) == 0 &&
        lk[lk.size() - low.size() - 1] == '.')
      best = k, ++count;
  }
  return count == 1 ? best : "";
}

namespace {

/// Stem and extension (with its dot, lower case) of a file name; a leading dot is not an extension.
std::pair<std::string, std::string> stem_and_extension(std::string_view name) {
  const std::size_t dot = name.rfind('.');
  if (dot == std::string_view::npos || dot == 0) return {lower(name), ""};
  return {lower(name.substr(0, dot)), lower(name.substr(dot))};
}

}  // namespace

std::string nearest_file_name(std::string_view name, const std::vector<std::string>& files) {
  constexpr std::size_t kLongest = 200;  // as nearest_name: a bound on the work
  if (name.empty() || name.size() > kLongest) return "";
  const auto [stem, ext] = stem_and_extension(name);
  const std::size_t allowed = stem.size() < 3 ? 0 : stem.size() < 7 ? 1 : 2;
  std::string best;
  std::size_t best_d = 0;
  for (const auto& f : files) {
    if (f == name || f.size() > kLongest) continue;
    const auto [s, e] = stem_and_extension(f);
    if (e != ext || digits_of(s) != digits_of(stem)) continue;
    const std::size_t d = edit_distance(stem, s);
    if (d <= allowed && (best.empty() || d < best_d)) best = f, best_d = d;
  }
  if (!best.empty()) return best;
  for (const auto& f : files)
    if (f != name && f.size() <= kLongest && stem_and_extension(f).first == stem) return f;
  return "";
}

std::string did_you_mean(std::string_view name, const std::vector<std::string>& known) {
  const std::string near = nearest_name(name, known);
  return near.empty() ? "" : "; did you mean '" + printable(near) + "'?";
}

std::string known_names(std::string_view name, const std::vector<std::string>& known, std::string_view what,
                        std::size_t max_listed) {
  if (known.empty()) return "(there are no " + std::string(what) + ")";
  std::string list;
  for (std::size_t i = 0; i < known.size() && i < max_listed; ++i) list += (list.empty() ? "" : ", ") + printable(known[i]);
  if (known.size() > max_listed) list += ", ... (" + std::to_string(known.size()) + " in all)";
  return "(the " + std::string(what) + " are: " + list + did_you_mean(name, known) + ")";
}

}  // namespace tunica
