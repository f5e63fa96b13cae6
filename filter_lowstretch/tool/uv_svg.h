// An SVG picture of a UV layout: faces coloured by stretch, with a colour scale.
#pragma once
#include <Eigen/Core>
#include <string>

namespace lowstretch {

// UV: #V x 2 in [0,1]^2; F: #F x 3; face_stretch: #F (1 = no stretch). Colours run on a log
// scale: blue below 1 (the map enlarges), white at 1, red above (the map shrinks, texture is
// stretched); flipped faces are black.
bool write_uv_svg(const std::string& path, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& F,
                  const Eigen::VectorXd& face_stretch, const std::string& title, std::string& error);

}  // namespace lowstretch
