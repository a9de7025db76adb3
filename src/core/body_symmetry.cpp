#include "src/core/body_symmetry.hpp"

#include "src/core/error.hpp"
#include "src/core/names.hpp"

namespace hydrocoef {

std::array<double, 6> BodyMirror::signs() const {
  std::array<double, 6> s{1, 1, 1, 1, 1, 1};
  s[axis] = -1.0;  // the linear component along the normal
  for (std::size_t a = 0; a < 3; ++a)
    if (a != axis) s[3 + a] = -1.0;  // the angular components about the other two axes
  return s;
}

RunKey BodyMirror::key(const RunKey& key) const {
  RunKey image = key;
  const auto s = signs();
  for (std::size_t i = 0; i < 6; ++i) {
    const double x = s[i] * key.nu_b[i];
    image.nu_b[i] = x == 0.0 ? 0.0 : x;
  }
  for (auto& [name, value] : image.disturbances)
    if (odd_disturbances.count(name)) value = value == 0.0 ? 0.0 : -value;
  return image;
}

bool BodyMirror::on_plane(const RunKey& key) const {
  const auto s = signs();
  for (std::size_t i = 0; i < 6; ++i)
    if (s[i] < 0 && key.nu_b[i] != 0.0) return false;
  for (const auto& [name, value] : key.disturbances)
    if (odd_disturbances.count(name) && value != 0.0) return false;
  return true;
}

std::string BodyMirror::text() const {
  static constexpr const char* kRules[3] = {
      "fore-aft: (u,v,w,p,q,r) -> (-u,v,w,p,-q,-r), (X,Y,Z,K,M,N) -> (-X,Y,Z,K,-M,-N)",
      "port-starboard: (u,v,w,p,q,r) -> (u,-v,w,-p,q,-r), (X,Y,Z,K,M,N) -> (X,-Y,Z,-K,M,-N)",
      "top-bottom: (u,v,w,p,q,r) -> (u,v,-w,-p,-q,r), (X,Y,Z,K,M,N) -> (X,Y,-Z,-K,-M,N)"};
  std::string out = std::string(kVelocityNames[axis]) + " (" + kRules[axis];
  for (const auto& name : odd_disturbances) out += ", " + name + " -> -" + name;
  return out + ")";
}

BodyMirror parse_body_mirror(std::string_view component, const std::vector<std::string>& odd_disturbances) {
  const auto index = velocity_index(component);
  if (!index || *index > 2)
    throw InputError("--mirror '" + printable_text(component, 20) +
                     "': expected u (fore-aft), v (port-starboard) or w (top-bottom)");
  BodyMirror mirror;
  mirror.axis = *index;
  for (const auto& name : odd_disturbances) {
    check_name(NameKind::Parameter, name, {}, "--mirror-odd");
    mirror.odd_disturbances.insert(name);
  }
  return mirror;
}

}  // namespace hydrocoef
