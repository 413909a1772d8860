#include "elements/membrane_compression.hpp"

#include <algorithm>
#include <cmath>

namespace tunica {

std::vector<char> compressed_points(const std::vector<MembranePoint>& points) {
  double scale = 0, strain = 0;
  for (const auto& p : points) {
    scale = std::max({scale, std::abs(p.sigma_principal(0)), std::abs(p.sigma_principal(1))});
    strain = std::max(strain, p.E.cwiseAbs().maxCoeff());
  }
  std::vector<char> out(points.size(), 0);
  if (strain <= kUnstrained) return out;  // stresses of round-off size only
  for (std::size_t i = 0; i < points.size(); ++i) out[i] = points[i].sigma_principal(1) < -kCompressionShare * scale;
  return out;
}

CompressionSize compression_size(const std::vector<MembranePoint>& points) {
  CompressionSize out;
  for (const auto& p : points) {
    out.compression = std::min(out.compression, p.sigma_principal(1));
    out.tension = std::max(out.tension, p.sigma_principal(0));
  }
  return out;
}

double compressed_fraction(const std::vector<MembranePoint>& points) {
  const std::vector<char> c = compressed_points(points);
  double total = 0, compressed = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    total += points[i].weight;
    if (c[i]) compressed += points[i].weight;
  }
  return total > 0 ? compressed / total : 0.0;
}

}  // namespace tunica
