#include "output/restart_fit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <tuple>
#include <vector>

namespace tunica {

namespace {

/// A key whose value differs between the run and the deck, with where to look in the deck: the
/// line of the key, or for a key no longer given, that of the nearest map or list that held it.
struct Change {
  std::string key, text;
  int line = 0, column = 0;
};

/// The keys of the fingerprint whose values differ, among those of the model and of the steps
/// the run has reached (step c.step, 0-based, once its fraction is past 0).
std::vector<Change> fingerprint_changes(const Model& m, const RestartRecord& r) {
  const Checkpoint& c = r.checkpoint;
  const auto reached = [&](const FingerprintEntry& e) { return e.step < c.step || (e.step == c.step && c.fraction > 0); };
  const auto shown = [](const std::string& v) { return v.empty() ? std::string("(not given)") : "'" + v + "'"; };
  std::map<std::string, const FingerprintEntry*> now, then;
  for (const auto& e : m.fingerprint)
    if (reached(e)) now[e.key] = &e;
  for (const auto& e : r.fingerprint)
    if (reached(e)) then[e.key] = &e;
  const auto change = [&](const std::string& key, const std::string& what) {
    Change ch;
    ch.key = key;
    std::string at = key;
    for (;;) {
      if (const auto it = m.fingerprint_places.find(at); it != m.fingerprint_places.end()) {
        std::tie(ch.line, ch.column) = it->second;
        break;
      }
      const std::size_t cut = at.find_last_of(".[");
      if (cut == std::string::npos || cut == 0) break;
      at.resize(cut);
    }
    ch.text = ch.line == 0 ? key + " " + what
              : at == key  ? fmt::format("line {}: {} {}", ch.line, key, what)
                           : fmt::format("line {} ('{}'): {} {}", ch.line, at, key, what);
    return ch;
  };
  std::vector<Change> changes;
  for (const auto& e : r.fingerprint) {
    if (!reached(e)) continue;
    const auto it = now.find(e.key);
    if (it == now.end())
      changes.push_back(change(e.key, fmt::format("(was {}, now not given)", shown(e.value))));
    else if (it->second->value != e.value)
      // A value recorded as a digest (a node list, a long text) says only that it changed.
      changes.push_back(change(e.key, e.value.rfind("digest ", 0) == 0
                                          ? std::string("(changed)")
                                          : fmt::format("(was {}, now {})", shown(e.value), shown(it->second->value))));
  }
  for (const auto& e : m.fingerprint)
    if (reached(e) && !then.count(e.key)) changes.push_back(change(e.key, fmt::format("(not given before, now {})", shown(e.value))));
  return changes;
}

/// The first change of each section of the deck (materials, parts, boundary, ...): what tells
/// two models apart, where the changes are many.
std::vector<Change> first_of_each_section(const std::vector<Change>& changes) {
  std::vector<Change> out;
  std::vector<std::string> seen;
  for (const Change& c : changes) {
    const std::string section = c.key.substr(0, c.key.find_first_of(".["));
    if (std::find(seen.begin(), seen.end(), section) != seen.end()) continue;
    seen.push_back(section);
    out.push_back(c);
  }
  return out;
}

/// One line per change, at most `max`, then how many more (of `what`).
std::string listed(const std::vector<Change>& changes, std::size_t max, const char* what = "") {
  std::string list;
  for (std::size_t k = 0; k < changes.size() && k < max; ++k) list += "\n  " + changes[k].text;
  if (changes.size() > max) list += fmt::format("\n  and {} more{}", changes.size() - max, what);
  return list;
}

}  // namespace

std::string check_restart_fits(const Model& m, const RestartRecord& r, const std::string& file) {
  const Checkpoint& c = r.checkpoint;
  const std::string folder = std::filesystem::path(file).parent_path().string();
  const std::vector<Change> changes = r.has_fingerprint ? fingerprint_changes(m, r) : std::vector<Change>{};
  const std::string keys = changes.size() == 1 ? "this key" : fmt::format("{} keys", changes.size());

  // Another model: what the state vector means differs, whatever the fingerprint says.
  const bool same_size = c.u.size() == m.num_dofs() && c.loads.boundary.size() == m.boundaries.size() &&
                         c.step_start.boundary.size() == m.boundaries.size() && c.loads.pressure.size() == m.loads.size() &&
                         c.step_start.pressure.size() == m.loads.size();
  if (!same_size)
    throw InputError(
        {file, 0, 0, ""},
        fmt::format("the run in {} is of another model than this deck: it was started with the deck '{}' and has {} "
                    "DOFs, {} boundary condition(s) and {} load(s), where this deck has {}, {} and {}{}\nRun this deck in a fresh "
                    "output folder (`tunica run {} -o <new folder>`), or continue that run with the deck that wrote it "
                    "(`tunica run {} --restart {}`).",
                    folder, r.deck, c.u.size(), c.loads.boundary.size(), c.loads.pressure.size(), m.num_dofs(),
                    m.boundaries.size(), m.loads.size(),
                    changes.empty() ? std::string(".")
                                    : fmt::format("; {} it depends on differ{}, the first of each section:{}", keys,
                                                  changes.size() == 1 ? "s" : "", listed(first_of_each_section(changes), 6, " section(s)")),
                    m.deck_file, r.deck, folder));

  // Past an inverse step (theory manual (13.10)) the state is a displacement from the reference that
  // step computed, which the restart file records as `reference_shift`: without it the run would
  // continue on the deck's imaged positions as its reference.
  const bool past_inverse = !m.steps.empty() && m.steps.front().moves_reference() && c.step > 0;
  if (past_inverse && c.reference_shift.size() != m.num_dofs())
    throw InputError(
        {file, 0, 0, ""},
        fmt::format("the run in {} is past the inverse step '{}', and its restart file records {} `reference_shift` "
                    "value(s) where this deck has {} DOFs: the zero-pressure reference the later steps continue from "
                    "is not known, and continuing on the deck's imaged geometry as the reference would be wrong. Run "
                    "the deck again from the start (`tunica run {} -o <new folder>`).",
                    folder, m.steps.front().name, c.reference_shift.size(), m.num_dofs(), m.deck_file));
  // Past a prestress step (theory manual §13.2) the state is one of the prestressed imaged geometry,
  // whose prestretch per Gauss point the restart file records as `prestress`.
  // (A run of the prestress step alone ends in it, at step fraction 1, with its prestress.)
  const bool past_prestress = !m.steps.empty() && m.steps.front().inverse && !m.steps.front().moves_reference() &&
                              (c.step > 0 || c.fraction >= 1.0 - 1e-12);
  if (past_prestress && c.prestress.empty())
    throw InputError({file, 0, 0, ""},
                     fmt::format("the run in {} is past the prestress step '{}', and its restart file records no "
                                 "`prestress`: the prestretch the later steps continue with is not known. Run the deck "
                                 "again from the start (`tunica run {} -o <new folder>`).",
                                 folder, m.steps.front().name, m.deck_file));
  if (!past_prestress && !c.prestress.empty())
    throw InputError({file, 0, 0, ""},
                     fmt::format("the run in {} records a `prestress` (a prestress step's), but this deck's step {} is "
                                 "not after a prestress step: it is another deck's run. Run this deck in a fresh output "
                                 "folder (`tunica run {} -o <new folder>`).",
                                 folder, c.step + 1, m.deck_file));
  if (!past_inverse && c.reference_shift.size() > 0)
    throw InputError({file, 0, 0, ""},
                     fmt::format("the run in {} records a `reference_shift` (a reference computed by an inverse step), "
                                 "but this deck's step {} is not after an inverse step: it is another deck's run. Run "
                                 "this deck in a fresh output folder (`tunica run {} -o <new folder>`).",
                                 folder, c.step + 1, m.deck_file));
  // The contact smoothing the run switched on, per pair (theory manual (9.2)): one width per pair of
  // the deck, and only where the deck leaves the pair's `smoothing` to the analysis.
  if (!c.contact_smoothing.empty()) {
    bool fits = c.contact_smoothing.size() == m.contacts.size();
    for (std::size_t k = 0; fits && k < m.contacts.size(); ++k)
      fits = c.contact_smoothing[k] == 0 || m.contacts[k].auto_smoothing;
    if (!fits)
      throw InputError({file, 0, 0, ""},
                       fmt::format("the run in {} switched on the smoothing of {} contact pair(s), but this deck has {} "
                                   "pair(s) (with the reverse passes of `passes: 2`) or gives one of them its own "
                                   "`smoothing`: it is another deck's run. Run this deck in a fresh output folder "
                                   "(`tunica run {} -o <new folder>`).",
                                   folder, c.contact_smoothing.size(), m.contacts.size(), m.deck_file));
  }

  // Every step done: a restart has nothing to run, unless the deck adds a step.
  if (c.step >= static_cast<int>(m.steps.size()) || (c.step == static_cast<int>(m.steps.size()) - 1 && c.fraction >= 1.0)) {
    const std::size_t last = std::min(static_cast<std::size_t>(c.step), m.steps.size() - 1);
    const std::string after = fmt::format("step {} '{}'", last + 1, m.steps[last].name);
    const std::string example = fmt::format(
        "`- {{name: more, increments: 10, set: {{{}: <its new value>}}}}`",
        !m.loads.empty() ? m.loads.front().name : !m.boundaries.empty() ? m.boundaries.front().name : "<boundary or load>");
    if (!changes.empty())
      throw InputError(
          {m.deck_file, changes.front().line, changes.front().column, ""},
          fmt::format("the deck differs from the run in {} in what its converged increments depend on ({}):{}\nThat run "
                      "has already completed every step of this deck, so a restart could only continue it, with the "
                      "values it had. To run the changed deck, start it in a fresh output folder (`tunica run {} -o "
                      "<new folder>`); to continue that run, undo the change and add a step after {} to `steps` (e.g. "
                      "{}).",
                      folder, keys, listed(changes, 8), m.deck_file, after, example));
    throw InputError({file, 0, 0, ""},
                     fmt::format("the run in {} has already completed every step of this deck (the last is {}), so "
                                 "nothing is left to run. To continue it, add a step after {} to `steps` (e.g. {}) and "
                                 "restart again; to run the deck again from the start, leave out --restart (`tunica run "
                                 "{} -o <new folder>`; into {} it replaces these results). (Solver settings, title and "
                                 "output are free to change on a restart and not compared: changed, they still leave "
                                 "nothing to run.)",
                                 folder, after, after, example, m.deck_file, folder));
  }

  if (!r.has_fingerprint)
    return file + " predates restart fingerprints: that the deck is unchanged is not checked";
  if (changes.empty()) return "";
  // The message stands at the first change's line; the list names each key.
  throw InputError(
      {m.deck_file, changes.front().line, changes.front().column, ""},
      fmt::format("the deck differs from the run to resume in what its converged increments depend on ({} in {}):{}\n"
                  "Undo the change (the run was started with the deck '{}'), or start a new run in a new folder. "
                  "Free to change on a restart: title, solver, "
                  "the steps not yet reached, each step's solver and name, and output other than history and "
                  "vtk_fields. A value respelt (30 kPa as 0.03 MPa) counts as a change.",
                  keys, file, listed(changes, 8), r.deck));
}

}  // namespace tunica
