// A cube map's faces and directions on the CPU: shaders/include/cube_face.h compiled as
// C++ with GLM's types (as physics/cloud_phase_table.h does).
#pragma once

#include <glm/glm.hpp>

namespace volgraph::physics::cube {

using namespace glm;

#include "shaders/include/cube_face.h"

}  // namespace volgraph::physics::cube

#include <glm/gtc/matrix_transform.hpp>

namespace volgraph::physics::cube {

// The face's axis and its up (−t's direction) in the faces' table above.
inline glm::dvec3 face_forward(int face) {
  const glm::dvec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  return axes[face];
}
inline glm::dvec3 face_up(int face) {
  if (face == 2) return {0, 0, -1};
  if (face == 3) return {0, 0, 1};
  return {0, 1, 0};
}

// World to clip for `face` seen from `position` (90°, square, depth [0, 1] from `near` to
// `far`), as volgraph's raster draws it (NDC +y the image's top): the pixel (i, j) of a face
// `size` wide looks along cube_texel_direction(face, (i, j), size) — a right-handed camera
// along the face's axis, mirrored left to right (a cube's faces are seen from outside).
inline glm::dmat4 face_view_projection(int face, const glm::dvec3& position, double near, double far) {
  const glm::dmat4 mirror = glm::scale(glm::dmat4(1), glm::dvec3(-1, 1, 1));
  return glm::perspectiveRH_ZO(glm::radians(90.0), 1.0, near, far) * mirror *
         glm::lookAtRH(position, position + face_forward(face), face_up(face));
}

}  // namespace volgraph::physics::cube
