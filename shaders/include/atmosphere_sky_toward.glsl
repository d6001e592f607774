// The sky's radiance toward a direction from the camera, per the sky pass's variant
// sky_view_lut: the sky-view LUT (include/atmosphere_lut.glsl) times the sun's irradiance,
// plus the sun's disk through the transmittance LUT and the ground
// (include/atmosphere_sky_lookup.glsl); a camera above the atmosphere, which the LUT cannot
// hold (it is made at the top), gets the per-pixel march (include/atmosphere_sky_march.glsl),
// as Hillaire 2020's RenderRayMarchingPS does. One text for the sky drawn behind the scene
// (atmosphere_sky.frag) and the sky in every direction (sky_cube.comp).
// The includer declares: atmosphere (AtmosphereParameters a), frame (SkyPassFrame f),
// transmittance, sky_view, multiscattering (the sky-view LUT when not wired: camera.y = 0),
// nearest and linear.
#ifndef VOLGRAPH_ATMOSPHERE_SKY_TOWARD_GLSL
#define VOLGRAPH_ATMOSPHERE_SKY_TOWARD_GLSL

vec3 sky_radiance_toward(vec3 direction) {
  const SkyViewOptions options = sky_view_options(frame.f);
  vec3 radiance;
  if (frame.f.camera.x > atmosphere_top(atmosphere.a)) {
    radiance = marched_sky_radiance(atmosphere.a, transmittance, nearest, multiscattering, linear, sky_frame(frame.f, false), direction, options);
  } else {
    const SkyFrame sky = sky_frame(frame.f, true);
    radiance = sky_view_lookup(atmosphere.a, sky_view, linear, sky, direction);
    if (options.sun_disk) radiance += sun_disk_radiance(atmosphere.a, transmittance, nearest, sky, direction, options.angular_radius, options.limb_darkening);
    if (options.ground) {
      radiance += seen_ground_radiance(atmosphere.a, transmittance, nearest, multiscattering, linear, sky, direction, options.sampling.multiscattering);
    }
  }
  return radiance * frame.f.sun.rgb;
}

#endif
