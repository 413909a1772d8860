#pragma once
// `tunica fit` and `tunica synthesize`: read, fit, write (docs/fit.md).
#include <cstdio>
#include <string>
#include <vector>

namespace tunica {

/// Options of `tunica fit`, as given on the command line.
struct FitCommand {
  std::string data;    ///< CSV file
  std::string output;  ///< output directory
  std::string model = "fung2d";
  std::string specimen;  ///< YAML file or inline map; "" = the file's `# specimen:` line
  std::string loss = "none";
  double loss_scale = 0.05;
  int starts = 0;                   ///< first N built-in starting points (0 = all)
  std::string start;                ///< extra start as an inline YAML map of constants, "" = none
  std::vector<std::string> select;  ///< COLUMN=VALUE row filters
  bool allow_non_monotone = false;
  bool plot = true;
  std::string material_name = "fitted";
};

/// Runs a fit and writes report.md, material.yaml, points.csv, curves.csv, plot_fit.py and
/// fit.png into `output`; prints a summary to `log` (null = quiet). InputError and
/// SolveError propagate to the caller (exit codes 2 and 3).
int run_fit_command(const FitCommand& command, std::FILE* log);

/// Writes synthetic data from a plan file to `output_csv` (synthetic_data.hpp).
int run_synthesize_command(const std::string& plan, const std::string& output_csv, std::FILE* log);

}  // namespace tunica
