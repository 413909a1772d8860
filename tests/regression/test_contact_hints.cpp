// What a run that stops with contact in play says (solver/failure_hints.hpp,
// contact_convergence_hint; user guide §6):
// - a Mooney–Rivlin balloon (ends held at r = 1.2 mm) inflated by pressure against a Fung artery
//   that carries no tension yet (no prestretch): it reaches the target with the Gauss–Newton contact
//   tangent of the iterations where slave nodes enter contact (theory manual (9.10));
// - the same pair under volume control: its active set chatters, and the run smooths the contact
//   law by itself (theory manual (9.2)) and reaches the target; with `smoothing: 0` the correction,
//   taken whole, drives the balloon's nodes into the artery until the residual grows without
//   bound, and the stop says why and what to change;
// - a compliant capsule filled under volume control inside an artery: the edge of its contact zone
//   chatters, and the run smooths the law (9.2) by itself and fills the artery; with `smoothing: 0`
//   the stop names the smoothing that settles it.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <tuple>

#include "../support/capture.hpp"
#include "../support/cli.hpp"
#include "../support/deck_files.hpp"

using namespace tunica;
using namespace tunica::test;

namespace {

/// The balloon in the artery: `steps` is the deck's steps section, `pair` more keys of the pair.
std::string balloon_in_artery(const std::string& steps, const std::string& pair = "") {
  return R"(title: balloon in an artery without prestretch
units: {length: mm, force: N}
materials:
  artery: {type: fung, c: 61.163 kPa, a1: 0.68238, a2: 0.60558, a4: 0.1067}
  balloon: {type: mooney_rivlin, b1: 0.5 MPa, b2: 0.125 MPa}
parts:
  artery:
    element: axisymmetric_membrane
    material: artery
    thickness: 0.122 mm
    mesh: {type: line, from: [1.561 mm, -1 mm], to: [1.561 mm, 5 mm], elements: 60}
  balloon:
    element: axisymmetric_membrane
    material: balloon
    thickness: 0.2 mm
    mesh: {type: line, from: [1.2 mm, 0 mm], to: [1.2 mm, 4 mm], elements: 40}
node_sets:
  balloon_ends: {part: balloon, nodes: [0, 40]}
boundary:
  artery_start: {node_set: artery.start, dofs: [z]}
  artery_end: {node_set: artery.end, dofs: [z]}
  balloon_ends: {node_set: balloon_ends, dofs: [r, z]}
loads:
  inflation: {type: pressure, part: balloon}
contact:
  balloon_artery: {slave: balloon, master: artery, master_orientation: reversed, penalty: 1e3 N/mm^3, offset: 0.16 mm)" + pair + R"(}
steps:
)" + steps + R"(
output:
  vtk: false
  history:
    - {quantity: pressure, load: inflation, unit: kPa}
    - {quantity: contact_force, contact: balloon_artery, unit: N}
)";
}

std::string stop_message(const std::string& deck) {
  const Model m = read_deck_text(deck, "balloon-artery.yaml");
  Capture c;
  Analysis a(m);
  try {
    a.run(c);
  } catch (const SolveError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ContactHints, ASlackMasterReachesTheTargetWithTheGaussNewtonContactTangent) {
  // Slave nodes that enter contact come in deep, and the exact tangent's curvature terms (in g_N)
  // made it indefinite there: Newton stalled at the first touch. The Gauss–Newton contact tangent
  // of those iterations (theory manual (9.10)) reaches the target.
  const Model m = read_deck_text(balloon_in_artery("  - {name: inflation, increments: 20, set: {inflation: 200 kPa}}"),
                                 "slack.yaml");
  Capture c;
  Analysis a(m);
  ASSERT_NO_THROW(a.run(c));
  EXPECT_NEAR(c.rows.back().values[0], 200.0, 1e-9);
  EXPECT_GT(c.rows.back().values[1], 0.0);  // in contact at the end (after cut-backs at the first touch)
}

TEST(ContactHints, TheSameModelWithTheArteryPrestretchedReachesTheTarget) {
  const Model m = read_deck_text(balloon_in_artery("  - {name: prestretch, increments: 4, set: {artery_end: 0.3 mm}}\n"
                                                   "  - {name: inflation, increments: 20, set: {inflation: 200 kPa}}"),
                                 "prestretched.yaml");
  Capture c;
  Analysis a(m);
  ASSERT_NO_THROW(a.run(c));
  EXPECT_NEAR(c.rows.back().values[0], 200.0, 1e-9);
  EXPECT_GT(c.rows.back().values[1], 0.0);  // in contact at the end
}

TEST(ContactHints, AVolumeControlThatDrivesTheSlaveIntoASlackMasterIsSmoothedByItself) {
  const std::string steps = "  - {name: start, increments: 2, set: {inflation: 20 kPa}}\n"
                            "  - {name: inflation, increments: 20, volume_control: {load: inflation, volume: 45 mm^3}}";
  // By default: the chattering front is smoothed (theory manual (9.2)) and the balloon reaches its volume.
  {
    const Model m = read_deck_text(balloon_in_artery(steps), "slack-volume.yaml");
    Capture c;
    Analysis a(m);
    ASSERT_NO_THROW(a.run(c));
    ASSERT_FALSE(c.retries.empty());
    EXPECT_NE(c.retries.back().second.find("on pair 'balloon_artery'"), std::string::npos) << c.retries.back().second;
    EXPECT_GT(c.rows.back().values[1], 0.0) << "the balloon presses on the artery";
    EXPECT_GT(a.model().contacts[0].law.smoothing, 0.0);
  }
  // With the plain law the deck asks for, the stop says why and what to change.
  const std::string what = stop_message(balloon_in_artery(steps, ", smoothing: 0 mm"));
  ASSERT_FALSE(what.empty()) << "the run converged";
  ASSERT_TRUE(what.find("the residual is not finite") != std::string::npos || what.find("diverging") != std::string::npos)
      << what;
  EXPECT_NE(what.find("Hint: under volume control each correction is taken whole"), std::string::npos) << what;
  EXPECT_NE(what.find("'balloon_artery'"), std::string::npos) << what;
  EXPECT_NE(what.find("part 'artery', carries almost no tension"), std::string::npos) << what;
  EXPECT_NE(what.find("axial prestretch"), std::string::npos) << what;
  EXPECT_NE(what.find("smaller `penalty`"), std::string::npos) << what;
  EXPECT_NE(what.find("more `increments`"), std::string::npos) << what;
}

namespace {

/// A compliant Mooney–Rivlin capsule (R 1 mm, a 6 mm cylinder between hemispherical caps) filled
/// under volume control inside a prestretched Fung artery: past its pressure maximum the capsule
/// spreads along the artery at a nearly constant pressure, and the nodes at the edge of the contact
/// zone carry almost no pressure. `smoothing`: the pair's extra key ("" for none).
std::string capsule_in_artery(const std::string& smoothing) {
  return R"(title: compliant capsule filling an artery
units: {length: mm, force: N}
materials:
  artery: {type: fung, c: 40 kPa, a1: 1.0, a2: 0.8, a4: 0.1}
  balloon: {type: mooney_rivlin, b1: 0.5 MPa, b2: 0.05 MPa}
parts:
  artery:
    element: axisymmetric_membrane
    material: artery
    thickness: 0.3 mm
    mesh: {type: line, from: [1.6 mm, -2 mm], to: [1.6 mm, 10 mm], elements: 60}
  balloon:
    element: axisymmetric_membrane
    material: balloon
    thickness: 0.05 mm
    mesh:
      - {type: arc, center: [0 mm, 1 mm], radius: 1 mm, start_angle: -90 deg, end_angle: 0 deg, elements: 10}
      - {type: line, from: [1 mm, 1 mm], to: [1 mm, 7 mm], elements: 30}
      - {type: arc, center: [0 mm, 7 mm], radius: 1 mm, start_angle: 0 deg, end_angle: 90 deg, elements: 10}
boundary:
  a_base: {node_set: artery.start, dofs: [z]}
  a_top: {node_set: artery.end, dofs: [z]}
  b_south: {node_set: balloon.start, dofs: [r, z]}
  b_north: {node_set: balloon.end, dofs: [r]}
loads:
  inflation: {type: pressure, part: balloon}
contact:
  b_a: {slave: balloon, master: artery, master_orientation: reversed, penalty: 1e3 N/mm^3, offset: 0.175 mm)" +
         smoothing + R"(}
steps:
  - {name: prestretch, increments: 4, set: {a_top: 0.6 mm}}
  - {name: dilate, increments: 20, volume_control: {load: inflation, volume: 70 mm^3}}
output:
  vtk: false
  history:
    - {quantity: pressure, load: inflation, unit: kPa}
    - {quantity: contact_force, contact: b_a, unit: N}
    - {quantity: volume, load: inflation, unit: mm^3}
)";
}

}  // namespace

TEST(ContactHints, AContactFrontThatChattersIsSmoothedByItselfAndFillsTheArtery) {
  // By default the run smooths the pair once the front chatters down to the smallest increment,
  // with 10⁻³ of the capsule's mean element length, (π/2 + 6 + π/2)/50 mm.
  const Model m = read_deck_text(capsule_in_artery(""), "capsule.yaml");
  Capture c;
  Analysis a(m);
  ASSERT_NO_THROW(a.run(c));
  ASSERT_EQ(c.retries.size(), 1u);
  EXPECT_NE(c.retries[0].second.find("`smoothing: 0.00018 mm` on pair 'b_a'"), std::string::npos)
      << c.retries[0].second;
  // The retry's attempts count on from the failed ones: (step, increment, attempt, iteration) is unique.
  std::set<std::tuple<int, int, int, int>> seen;
  for (const Iteration& it : c.iterations)
    EXPECT_TRUE(seen.insert({it.info.step, it.info.increment, it.info.attempt, it.rec.iteration}).second)
        << "step " << it.info.step << " increment " << it.info.increment << " attempt " << it.info.attempt
        << " iteration " << it.rec.iteration;
  // (chords of the caps: a little below the arc lengths)
  EXPECT_NEAR(a.model().contacts[0].law.smoothing, 1e-3 * (M_PI + 6) / 50, 1e-3 * 1e-3 * (M_PI + 6) / 50);
  const auto& last = c.rows.back().values;
  EXPECT_NEAR(last[2], 70.0, 1e-6 * 70);
  EXPECT_GT(last[1], 0.1) << "the capsule presses on the artery";
  // The pressure stays near the capsule's own maximum while it spreads (44.5 … 48.4 kPa).
  EXPECT_GT(last[0], 44.0);
  EXPECT_LT(last[0], 50.0);

  // A restart continues with the smoothing the run switched on (Checkpoint::contact_smoothing).
  const Checkpoint done = a.checkpoint();
  ASSERT_EQ(done.contact_smoothing.size(), 1u);
  const Model more = read_deck_text(
      test::replace(capsule_in_artery(""), "volume: 70 mm^3}}\n",
                    "volume: 70 mm^3}}\n  - {name: more, increments: 2, volume_control: {load: inflation, volume: 72 "
                    "mm^3}}\n"),
      "capsule-more.yaml");
  Capture r;
  Analysis resumed(more);
  ASSERT_NO_THROW(resumed.run(r, &done));
  EXPECT_EQ(resumed.model().contacts[0].law.smoothing, done.contact_smoothing[0]);
  EXPECT_NEAR(r.rows.back().values[2], 72.0, 1e-6 * 72);

  // The same smoothing given in the deck: the same state, without a retry.
  const Model given = read_deck_text(capsule_in_artery(", smoothing: 0.00018 mm"), "capsule-smoothed.yaml");
  Capture g;
  Analysis b(given);
  ASSERT_NO_THROW(b.run(g));
  EXPECT_TRUE(g.retries.empty());
  EXPECT_NEAR(g.rows.back().values[0], last[0], 0.01 * last[0]);
}

TEST(ContactHints, AContactFrontThatChattersWithThePlainLawNamesTheSmoothing) {
  const std::string what = stop_message(capsule_in_artery(", smoothing: 0 mm"));
  ASSERT_FALSE(what.empty()) << "the run converged";
  EXPECT_NE(what.find("the contact active set changed at"), std::string::npos) << what;
  EXPECT_NE(what.find("`smoothing: 0.00018 mm` on pair 'b_a'"), std::string::npos) << what;
}

namespace {

/// A very compliant Mooney–Rivlin capsule (b1 + b2 = 25 kPa, H 0.05 mm, R 1 mm: its free-inflation
/// pressure levels off near 2H(b1 + b2)/R ≈ 2.5 kPa), poles held, inside a prestretched Fung artery;
/// `inflate` is the inflation step.
std::string soft_capsule_in_artery(const std::string& inflate) {
  return R"(title: very compliant capsule in a prestretched artery
units: {length: mm, force: N}
materials:
  artery: {type: fung, c: 40 kPa, a1: 1.2, a2: 1.0, a4: 0.15}
  balloon: {type: mooney_rivlin, b1: 20 kPa, b2: 5 kPa}
parts:
  artery:
    element: axisymmetric_membrane
    material: artery
    thickness: 0.25 mm
    mesh: {type: line, from: [1.5 mm, 0 mm], to: [1.5 mm, 10 mm], elements: 40}
  balloon:
    element: axisymmetric_membrane
    material: balloon
    thickness: 0.05 mm
    mesh:
      - {type: arc, center: [0 mm, 3 mm], radius: 1 mm, start_angle: -90 deg, end_angle: 0 deg, elements: 8}
      - {type: line, from: [1 mm, 3 mm], to: [1 mm, 7 mm], elements: 32}
      - {type: arc, center: [0 mm, 7 mm], radius: 1 mm, start_angle: 0 deg, end_angle: 90 deg, elements: 8}
boundary:
  a_base: {node_set: artery.start, dofs: [z]}
  a_top: {node_set: artery.end, dofs: [z]}
  b_south: {node_set: balloon.start, dofs: [r, z]}
  b_north: {node_set: balloon.end, dofs: [r, z]}
loads:
  inflation: {type: pressure, part: balloon}
contact:
  b_a: {slave: balloon, master: artery, master_orientation: reversed, penalty: 500 N/mm^3, offset: 0.15 mm}
steps:
  - {name: prestretch, increments: 4, set: {a_top: 3 mm}}
)" + inflate + R"(
output:
  vtk: false
  history:
    - {quantity: pressure, load: inflation, unit: kPa}
    - {quantity: contact_force, contact: b_a, unit: N}
    - {quantity: volume, load: inflation, unit: mm^3}
)";
}

}  // namespace

TEST(ContactHints, ABalloonThatSpreadsUnderPressureControlIsToldToControlItsVolume) {
  const std::string what =
      stop_message(soft_capsule_in_artery("  - {name: inflate, increments: 20, set: {inflation: 60 kPa}}"));
  ASSERT_FALSE(what.empty()) << "the run converged";
  EXPECT_NE(what.find("the contact active set changed at"), std::string::npos) << what;
  EXPECT_NE(what.find("The slave 'balloon' is inflated by 'inflation' under pressure control"), std::string::npos)
      << what;
  EXPECT_NE(what.find("`volume_control: {load: inflation, volume: <the volume to reach>}` on this step"),
            std::string::npos)
      << what;
  EXPECT_EQ(what.find("`passes: 2`"), std::string::npos) << what;

  // What the hint names: the volume, past the capsule's pressure maximum, at a few kPa.
  const Model m = read_deck_text(
      soft_capsule_in_artery("  - {name: start, increments: 2, set: {inflation: 2 kPa}}\n"
                             "  - {name: inflate, increments: 20, volume_control: {load: inflation, volume: 70 mm^3}}"),
      "soft-capsule-volume.yaml");
  Capture c;
  Analysis a(m);
  ASSERT_NO_THROW(a.run(c));
  const auto& last = c.rows.back().values;
  EXPECT_NEAR(last[2], 70.0, 1e-6 * 70);
  EXPECT_GT(last[1], 0.0) << "the capsule presses on the artery";
  EXPECT_GT(last[0], 3.0);
  EXPECT_LT(last[0], 10.0);
}

TEST(ContactHints, APairThatNeverTouchedIsNotedWithTheLoadOnTheWrongPart) {
  // The inflation written on the artery instead of the balloon: the artery inflates away from the
  // balloon, the run ends normally, and the note says the pair never touched and why.
  const std::string wrong = test::replace(
      balloon_in_artery("  - {name: prestretch, increments: 2, set: {artery_end: 0.3 mm}}\n"
                        "  - {name: inflation, increments: 4, set: {inflation: 20 kPa}}"),
      "inflation: {type: pressure, part: balloon}", "inflation: {type: pressure, part: artery}");
  const std::string dir = testing::TempDir() + "tunica-contact-hints";
  const Outcome o = run_cli("run " + write_deck_file("tunica-contact-hints", "wrong-part.yaml", wrong) + " -q -o " +
                            dir + "-wrong");
  EXPECT_EQ(o.exit_code, 0) << o.output;
  EXPECT_NE(o.output.find("note: contact pair 'balloon_artery' never touched: no node of part 'balloon' came within "
                          "its offset of its master 'artery'"),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("No load acts on part 'balloon' (the loads: 'inflation' on part 'artery'): if it was to be "
                          "pressed onto its master 'artery', check the loads' `part`."),
            std::string::npos)
      << o.output;
  // The load on the balloon: it touches, no note.
  const std::string right = test::replace(wrong, "inflation: {type: pressure, part: artery}",
                                          "inflation: {type: pressure, part: balloon}");
  const Outcome ok = run_cli("run " + write_deck_file("tunica-contact-hints", "right-part.yaml",
                                                      test::replace(right, "inflation: 20 kPa", "inflation: 200 kPa")) +
                             " -q -o " + dir + "-right");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_EQ(ok.output.find("never touched"), std::string::npos) << ok.output;
}
