// For a fragment whose view-dependent terms createShaderView keeps in a float target (its `cache`
// option). Include it after the fragment's `vec4 viewTerms()`. Compiled with CACHE_PASS, main()
// writes viewTerms() to the target; otherwise keptTerms() gives them, read back from the target
// (CACHED) or computed on the spot (a GPU without float render targets), and the fragment's own
// main(), inside #ifndef CACHE_PASS, finishes the picture from them with the live uniforms.
#ifdef CACHE_PASS
void main() {
  fragColor = viewTerms();
}
#endif

#ifdef CACHED
uniform sampler2D uCache;
#endif

vec4 keptTerms() {
#ifdef CACHED
  return texelFetch(uCache, ivec2(gl_FragCoord.xy), 0);
#else
  return viewTerms();
#endif
}
