#include "fit/fit_plot.hpp"

#include <cstdlib>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>  // environ

#include <filesystem>
#include <vector>

#include "output/atomic_file.hpp"

namespace tunica {

const std::string& fit_plot_script() {
  static const std::string script = R"PY(#!/usr/bin/python3
"""Plots a `tunica fit` result: measured points against the fitted thin-tube curves.

Usage: /usr/bin/python3 plot_fit.py DIR [TITLE]   (reads DIR/points.csv, DIR/curves.csv; writes DIR/fit.png)
Written by `tunica fit`; needs matplotlib (Debian: python3-matplotlib).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_columns(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    head, body = rows[0], rows[1:]
    return {h: [float(r[i]) for r in body] for i, h in enumerate(head)}


def column(cols, prefix):
    """The column whose name starts with `prefix`, and the rest of its name (the unit)."""
    for name, values in cols.items():
        if name.startswith(prefix):
            return values, name[len(prefix):].replace("_per_", "/")
    raise KeyError(prefix)


def main():
    out = sys.argv[1]
    title = sys.argv[2] if len(sys.argv) > 2 else ""
    pts = read_columns(os.path.join(out, "points.csv"))
    cur = read_columns(os.path.join(out, "curves.csv"))
    size = "outer_diameter" if any(h.startswith("outer_diameter") for h in pts) else "radius"
    size_label = "outer diameter" if size == "outer_diameter" else "mid-surface radius"

    p_meas, pu = column(pts, "pressure_measured_")
    f_meas, fu = column(pts, "axial_force_measured_")
    s_meas, lu = column(pts, size + "_measured_")
    st_meas, _ = column(pts, "S_theta_measured_")
    sz_meas, _ = column(pts, "S_z_measured_")
    p_cur, _ = column(cur, "pressure_")
    f_cur, _ = column(cur, "axial_force_")
    s_cur, _ = column(cur, size + "_")
    st_cur, _ = column(cur, "S_theta_")
    sz_cur, _ = column(cur, "S_z_")

    fig, axes = plt.subplots(2, 2, figsize=(10, 8))
    (ax_p, ax_f), (ax_st, ax_sz) = axes
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    levels = sorted(set(int(v) for v in pts["level"]))
    curve_levels = set(int(v) for v in cur["level"]) if cur.get("level") else set()
    single_labelled = False
    for level in levels:
        c = colours[level % len(colours)]
        idx = [i for i, v in enumerate(pts["level"]) if int(v) == level]
        lz = pts["lambda_z"][idx[0]]
        many = level in curve_levels
        label = f"λz = {lz:.4g}" if many else None
        if not many and not single_labelled:
            label, single_labelled = "λz with one point", True
        style = dict(color=c if many else "0.6", marker="o", ms=4, ls="none", mfc="none")
        ax_p.plot([s_meas[i] for i in idx], [p_meas[i] for i in idx], label=label, **style)
        ax_f.plot([p_meas[i] for i in idx], [f_meas[i] for i in idx], **style)
        ax_st.plot([pts["E_theta"][i] for i in idx], [st_meas[i] for i in idx], **style)
        ax_sz.plot([pts["E_theta"][i] for i in idx], [sz_meas[i] for i in idx], **style)
        if many:
            jdx = [j for j, v in enumerate(cur["level"]) if int(v) == level]
            ax_p.plot([s_cur[j] for j in jdx], [p_cur[j] for j in jdx], color=c)
            ax_f.plot([p_cur[j] for j in jdx], [f_cur[j] for j in jdx], color=c)
            ax_st.plot([cur["E_theta"][j] for j in jdx], [st_cur[j] for j in jdx], color=c)
            ax_sz.plot([cur["E_theta"][j] for j in jdx], [sz_cur[j] for j in jdx], color=c)
    ax_p.set(xlabel=f"{size_label} [{lu}]", ylabel=f"pressure [{pu}]", title="pressure–size")
    ax_f.set(xlabel=f"pressure [{pu}]", ylabel=f"axial force [{fu}]", title="axial force")
    ax_st.set(xlabel="Eθ", ylabel="Sθ [kPa]", title="hoop stress (cf. paper Fig. 1)")
    ax_sz.set(xlabel="Eθ", ylabel="Sz [kPa]", title="axial stress (cf. paper Fig. 2)")
    for ax in axes.flat:
        ax.grid(True, alpha=0.3)
    ax_p.legend(title="points: measured, lines: fitted", fontsize=8, title_fontsize=8)
    if title:
        fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "fit.png"), dpi=120)


if __name__ == "__main__":
    main()
)PY";
  return script;
}

std::string plot_fit(const std::string& dir, const std::string& title) {
  const std::string script = (std::filesystem::path(dir) / "plot_fit.py").string();
  write_file_atomically(script, fit_plot_script());
  const char* env = std::getenv("TUNICA_PYTHON");
  const std::string python = env && *env ? env : "/usr/bin/python3";
  if (!std::filesystem::exists(python)) return python + " not found (set TUNICA_PYTHON to a python3 with matplotlib)";
  // Run python directly (no shell), its stderr into plot_fit.log.
  const std::string log = dir + "/plot_fit.log";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> args = {python, script, dir, title};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, python.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  if (spawned != 0 || waitpid(pid, &status, 0) < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return "plot_fit.py failed (see " + log + "; it needs matplotlib)";
  std::filesystem::remove(dir + "/plot_fit.log");
  return "";
}

}  // namespace tunica
