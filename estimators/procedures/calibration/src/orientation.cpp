#include <cctype>

#include "plumb/calibration/types.hpp"

namespace plumb::calibration {

Eigen::Vector3d Orientation::up() const {
  Eigen::Vector3d u = Eigen::Vector3d::Zero();
  if (known()) u[axis] = sign;
  return u;
}

std::string Orientation::label() const {
  if (!known()) return "any";
  std::string s = face_label(face());
  if (rotation_deg != 0) s += "@" + std::to_string(rotation_deg);
  return s;
}

std::string face_label(int face) {
  static const char* const kLabels[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
  return face >= 0 && face < 6 ? kLabels[face] : "?";
}

Orientation parse_orientation(const std::string& text) {
  Orientation o;
  if (text == "any" || text == "?" || text.empty()) return o;
  const auto fail = [&] {
    throw CalibrationError("orientation '" + text +
                           "' is not one of +x -x +y -y +z -z (optionally @0 @90 @180 @270) or any");
  };
  if (text.size() < 2 || (text[0] != '+' && text[0] != '-')) fail();
  const char axis = static_cast<char>(std::tolower(static_cast<unsigned char>(text[1])));
  if (axis < 'x' || axis > 'z') fail();
  o.axis = axis - 'x';
  o.sign = text[0] == '+' ? 1 : -1;
  if (text.size() > 2) {
    if (text[2] != '@') fail();
    const std::string rot = text.substr(3);
    if (rot == "0") o.rotation_deg = 0;
    else if (rot == "90") o.rotation_deg = 90;
    else if (rot == "180") o.rotation_deg = 180;
    else if (rot == "270") o.rotation_deg = 270;
    else fail();
  }
  return o;
}

const Parameter* find_parameter(const Result& r, const std::string& name) {
  for (const auto& p : r.parameters)
    if (p.name == name) return &p;
  return nullptr;
}

}  // namespace plumb::calibration
