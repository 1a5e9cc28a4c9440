// Linear radiance to the 8-bit display colour: exposure, an exponential tone curve, gamma 2.2.
#ifndef OASIS_OUTPUT_GLSL
#define OASIS_OUTPUT_GLSL
vec3 displayEncode(vec3 radiance) {
    vec3 mapped = vec3(1.0) - exp(-max(radiance, vec3(0.0)) * frame.depthRange.w);
    return pow(mapped, vec3(1.0 / 2.2));
}

// TONE_MAP_FUSED: the pass that writes a pixel's colour last writes Final too, so no separate
// ToneMapPass runs. ToneMapPass reads Radiance as stored (half floats), so the fused value is
// converted the same way first, with bit arithmetic (packHalf2x16 needs GLSL 4.20 and rounds to
// nearest). llvmpipe's render-target conversion drops the low bits (toward zero: measured, the
// fused frame then equals the separate pass's bit for bit; rounding to nearest left 1/255 apart on
// 1.7 % of the pixels); a driver that rounds differs from the separate pass by 1/255 at most.
float storedAsHalf(float x) {
    float a = abs(x);
    if (isnan(x) || a >= 65520.0) return x;  // displayEncode maps these alike either way
    // Half's subnormals are multiples of 2^-24; above them 10 of float's 23 mantissa bits stay.
    if (a < 6.103515625e-05) return trunc(x * 16777216.0) / 16777216.0;
    return uintBitsToFloat(floatBitsToUint(x) & ~0x1fffu);
}
vec3 storedAsRadiance(vec3 radiance) {
    return vec3(storedAsHalf(radiance.r), storedAsHalf(radiance.g), storedAsHalf(radiance.b));
}
vec4 finalColour(vec3 radiance) { return vec4(displayEncode(storedAsRadiance(radiance)), 1.0); }
#endif
