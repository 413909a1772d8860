#pragma once
// The figure of a fit: a small matplotlib script, written into the output
// directory beside points.csv and curves.csv and run with Debian's
// /usr/bin/python3 (which has matplotlib), so that the directory can re-plot itself:
//     /usr/bin/python3 DIR/plot_fit.py DIR
// Panels: pressure vs size, axial force vs pressure, and the paper's Fig. 1 and 2
// analogues Sθ vs Eθ and Sz vs Eθ, measured points against the fitted curves.
#include <string>

namespace tunica {

/// The Python source of plot_fit.py.
const std::string& fit_plot_script();

/// Writes DIR/plot_fit.py and runs it (interpreter: $TUNICA_PYTHON or /usr/bin/python3),
/// producing DIR/fit.png with `title` on top. Returns "" on success, else why not.
std::string plot_fit(const std::string& dir, const std::string& title);

}  // namespace tunica
