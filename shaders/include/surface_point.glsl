// A translucent surface's fragment as translucent_surface.glsl hands it to `write_layer`
// beside its layer; each translucency shader includes it before defining write_layer.
#ifndef VOLGRAPH_SURFACE_POINT_GLSL
#define VOLGRAPH_SURFACE_POINT_GLSL

// Where the layer lies, for the draws that need more than its colours (screen-space
// refraction, the OIT weight).
struct SurfacePoint {
  vec3 position;     // world (m)
  vec3 to_camera;    // unit
  vec3 normal;       // unit, toward the camera
  float distance;    // from the camera (m)
  float view_depth;  // m
  float inside;      // the path inside along the view ray (m): inside_path's
};

#endif
