// A faint wire along every pass: where the interpolated pass index is a whole number.
// Declarations: replaces //VTK::Color::Dec (kept). Implementation: appended to //VTK::Light::Impl.
//DECLARATIONS
in float passCoordVSOutput;
//IMPLEMENTATION
{
  float passesPerPixel = max(fwidth(passCoordVSOutput), 1e-6);
  float passDistance = abs(fract(passCoordVSOutput - 0.5) - 0.5) / passesPerPixel;
  float passLine = 1.0 - clamp(passDistance - 0.5, 0.0, 1.0);
  // Wires closer than a few pixels would cover the colours: they fade out from 6 pixels apart
  // to 2.
  float apart = clamp((1.0 / passesPerPixel - 2.0) / 4.0, 0.0, 1.0);
  gl_FragData[0].rgb = mix(gl_FragData[0].rgb, vec3(0.08), passLine * passWireStrength * apart);
}
