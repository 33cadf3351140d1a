// The glow of the selected line's samples: each point sprite fades from a hot centre to a
// transparent rim. Replaces //VTK::Light::Impl of the highlight points' mapper.
{
  vec2 spriteCoord = gl_PointCoord * 2.0 - 1.0;
  float radius2 = dot(spriteCoord, spriteCoord);
  if (radius2 > 1.0) discard;
  float core = exp(-6.0 * radius2);
  gl_FragData[0] = vec4(mix(glowRim, glowCore, core), clamp(1.2 * core + 0.25 * (1.0 - radius2), 0.0, 1.0));
}
