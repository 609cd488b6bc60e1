// What the shader makes of a stored texel: the unit shading normal and the effective roughness
// α' (and the equivalent Blinn-Phong exponent s' = 2/α'² − 2) for a base roughness α.
// Per technique (formulas in lobeFormulas.js):
//   naive         n = normalize(N_a); α' = α (the length is thrown away, as three.js's
//                 normal_fragment_maps does)
//   renormalized  n = N; α' = α
//   toksvig       n = normalize(N_a); α' from σ² = (1 − |N_a|)/|N_a| (Toksvig, "Mipmapping
//                 Normal Maps", NVIDIA 2004): for Blinn-Phong,
//                 s/(1 + sσ²) equals 2/α'² − 2 exactly when s = 2/α² − 2 (derived, tested)
//   vmf           n = N; α' = √(α² + 2/κ(r̄)) (Han et al., SIGGRAPH 2007; the 2/κ as in
//                 TheRealMJP/SpecularAA and Filament's roughness-prefilter)
//   lean          n = normalize(bx, by, 1); anisotropic Σ, α' = √(α² + tr C) (Olano & Baker,
//                 "LEAN Mapping", I3D 2010)
//   clean         n = normalize(bx, by, 1); α' = √(α² + σ²) (Baker, GDC 2011; σ² sums both axes,
//                 so this is α² + 2v with v the per-axis slope variance)
// With channels = 2 the stored x, y get z = √(1 − x² − y²) first (BC5-style two-channel normals).
import {
  alphaFromExponent, cleanAlpha, exponentFromAlpha, leanCovariance, reconstructZ, toksvigAlpha, vmfAlpha,
} from './lobeFormulas.js';

function baseAlpha({ alpha, exponent }) {
  const a = alpha ?? (exponent === undefined ? undefined : alphaFromExponent(exponent));
  if (typeof a !== 'number' || !(a > 0 && a <= 1)) throw new RangeError(`alpha must be in (0, 1], got ${String(a)}`);
  return a;
}

function normalize3(x, y, z, out) {
  const len = Math.hypot(x, y, z);
  const inv = len > 0 ? 1 / len : 0;
  out.normal[0] = x * inv;
  out.normal[1] = y * inv;
  out.normal[2] = len > 0 ? z * inv : 1;
  return len;
}

/** A reusable result object for texelLobe (no allocation per texel in level loops). */
export function createLobe() {
  return { normal: [0, 0, 1], length: 1, alpha: 0, alphaMajor: 0, alphaMinor: 0, covariance: null };
}

/**
 * texelLobe(chain, level, texel, { alpha } | { exponent }, out = createLobe()) → out with
 * normal (unit, what the shader shades with), length (|stored normal| after z reconstruction, or
 * NaN for LEAN/CLEAN, which store no normal), alpha (isotropic α'), alphaMajor/alphaMinor (equal
 * except for LEAN) and, for LEAN, covariance { sxx, syy, sxy, major, minor } (base lobe included).
 */
export function texelLobe(chain, level, texel, base, out = createLobe()) {
  const a = baseAlpha(base);
  const d = chain.levels[level].data;
  const o = texel * chain.components;
  out.covariance = null;
  if (chain.technique === 'lean' || chain.technique === 'clean') {
    normalize3(d[o], d[o + 1], 1, out);
    out.length = NaN;
    if (chain.technique === 'lean') {
      const cov = leanCovariance(d[o], d[o + 1], d[o + 2], d[o + 3], d[o + 4], a);
      out.covariance = cov;
      out.alpha = Math.sqrt(cov.major + cov.minor);
      out.alphaMajor = Math.sqrt(2 * cov.major);
      out.alphaMinor = Math.sqrt(2 * cov.minor);
    } else {
      out.alpha = cleanAlpha(d[o], d[o + 1], d[o + 2], a);
      out.alphaMajor = out.alpha;
      out.alphaMinor = out.alpha;
    }
    return out;
  }
  const x = d[o];
  const y = d[o + 1];
  const z = chain.channels === 3 ? d[o + 2] : Math.fround(reconstructZ(x, y));
  out.length = Math.fround(normalize3(x, y, z, out));
  if (chain.technique === 'toksvig') out.alpha = toksvigAlpha(out.length, a);
  else if (chain.technique === 'vmf') out.alpha = vmfAlpha(d[o + chain.channels], a);
  else out.alpha = a;
  out.alphaMajor = out.alpha;
  out.alphaMinor = out.alpha;
  return out;
}

/**
 * effectiveRoughness(chain, level, { alpha } | { exponent }) → per texel of the level,
 * Float32Arrays { alpha, exponent, alphaMajor, alphaMinor, length } (row-major like the level)
 * for heatmaps. exponent = 2/α'² − 2; length is NaN for LEAN/CLEAN.
 */
export function effectiveRoughness(chain, level, base) {
  const n = chain.levels[level].size ** 2;
  const res = {
    alpha: new Float32Array(n),
    exponent: new Float32Array(n),
    alphaMajor: new Float32Array(n),
    alphaMinor: new Float32Array(n),
    length: new Float32Array(n),
  };
  const lobe = createLobe();
  for (let t = 0; t < n; t++) {
    texelLobe(chain, level, t, base, lobe);
    res.alpha[t] = lobe.alpha;
    res.exponent[t] = exponentFromAlpha(lobe.alpha);
    res.alphaMajor[t] = lobe.alphaMajor;
    res.alphaMinor[t] = lobe.alphaMinor;
    res.length[t] = lobe.length;
  }
  return res;
}
