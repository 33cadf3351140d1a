// Iso-lines of the coloured quantity over the surface, drawn after lighting. The colour map's
// texture coordinate s runs 0..1 over the map's range, so lines at multiples of 1/isoBands are
// equal-value contours: where adjacent passes disagree, the contours zig-zag across them.
// Replaces //VTK::Light::Impl (appended after VTK's own lighting code).
{
  float isoValue = tcoordVCVSOutput.s * isoBands;
  float isoDistance = abs(fract(isoValue - 0.5) - 0.5) / max(fwidth(isoValue), 1e-6);
  float isoLine = 1.0 - clamp(isoDistance - 0.5, 0.0, 1.0);
  gl_FragData[0].rgb = mix(gl_FragData[0].rgb, gl_FragData[0].rgb * 0.3, isoLine * isoStrength);
}
