#include "tool/uv_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <vector>

namespace lowstretch {

namespace {

// Blue -> white -> red for t in [0, 1].
std::string colour(double t) {
  t = std::max(0.0, std::min(1.0, t));
  const double r = t < 0.5 ? 2 * t : 1.0, g = t < 0.5 ? 2 * t : 2 * (1 - t), b = t < 0.5 ? 1.0 : 2 * (1 - t);
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", int(r * 255), int(g * 255), int(b * 255));
  return buf;
}

}  // namespace

bool write_uv_svg(const std::string& path, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& F,
                  const Eigen::VectorXd& face_stretch, const std::string& title, std::string& error) {
  std::vector<double> finite;
  for (Eigen::Index f = 0; f < face_stretch.size(); ++f)
    if (std::isfinite(face_stretch(f))) finite.push_back(face_stretch(f));
  // Diverging log scale: 1/range (blue) .. 1 (white) .. range (red), range from the 1st and
  // 99th percentiles so that a few extreme faces do not wash out the picture.
  double range = 2;
  if (!finite.empty()) {
    std::sort(finite.begin(), finite.end());
    const double low = finite[size_t(0.01 * double(finite.size() - 1))], high = finite[size_t(0.99 * double(finite.size() - 1))];
    range = std::max({1.0 + 1e-9, high, low > 0 ? 1 / low : 1.0});
  }
  const double log_range = std::log(range);
  const double size = 800, margin = 20, bar = 60;
  const std::string temporary = path + ".partial";
  std::ofstream out(temporary);
  out.setf(std::ios::fixed);
  out.precision(1);  // a tenth of a pixel
  out << "<svg xmlns='http://www.w3.org/2000/svg' width='" << size + 2 * margin + bar << "' height='"
      << size + 2 * margin + 30 << "'>\n<rect width='100%' height='100%' fill='white'/>\n";
  out << "<text x='" << margin << "' y='" << margin + size + 25 << "' font-family='sans-serif' font-size='14'>" << title
      << "</text>\n<g stroke='#00000030' stroke-width='0.3'>\n";
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const double s = face_stretch(f);
    const std::string fill = std::isfinite(s) && s > 0 ? colour(0.5 + 0.5 * std::log(s) / log_range) : "#000000";
    out << "<polygon fill='" << fill << "' points='";
    for (int k = 0; k < 3; ++k)
      out << margin + size * UV(F(f, k), 0) << ',' << margin + size * (1 - UV(F(f, k), 1)) << ' ';
    out << "'/>\n";
  }
  out << "</g>\n";
  // Colour scale: 1/range at the bottom, 1 in the middle, range at the top.
  const double x = 2 * margin + size;
  for (int i = 0; i < 100; ++i)
    out << "<rect x='" << x << "' y='" << margin + size * (1 - (i + 1) / 100.0) << "' width='15' height='"
        << size / 100.0 + 0.5 << "' fill='" << colour(i / 99.0) << "'/>\n";
  char top_label[32], bottom_label[32];
  std::snprintf(top_label, sizeof top_label, "%.3g", range);
  std::snprintf(bottom_label, sizeof bottom_label, "%.3g", 1 / range);
  out << "<text x='" << x + 18 << "' y='" << margin + 10 << "' font-family='sans-serif' font-size='12'>" << top_label
      << "</text>\n<text x='" << x + 18 << "' y='" << margin + size / 2 << "' font-family='sans-serif' font-size='12'>1</text>\n"
      << "<text x='" << x + 18 << "' y='" << margin + size << "' font-family='sans-serif' font-size='12'>" << bottom_label << "</text>\n"
      << "<text x='" << x << "' y='" << margin + size + 25 << "' font-family='sans-serif' font-size='12'>stretch</text>\n</svg>\n";
  out.close();
  if (!out || std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    error = "cannot write " + path;
    return false;
  }
  return true;
}

}  // namespace lowstretch
