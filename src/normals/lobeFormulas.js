// The per-texel lobe formulas of each technique, in float64 (the shader's contract).
// α is the GGX/Beckmann roughness (α = perceptual roughness², Burley, "Physically Based Shading
// at Disney", SIGGRAPH 2012), s the Blinn-Phong exponent. For small values every isotropic
// method is α'² ≈ α² + 2v with v the per-axis slope variance (derived: the small-variance limit
// of each formula below). The variances of independent slopes add whatever their distributions;
// what Beckmann adds is closure: its slopes are Gaussian, and a Gaussian lobe widened by Gaussian
// footprint slopes stays a Gaussian, so the sum is again a Beckmann lobe (the normal-mips panel
// shades with Beckmann). That needs the footprint's slopes to be Gaussian too; the grooves and
// checker maps are bimodal (the panel's inspector shows it), so there the sum keeps the second
// moment but not the lobe's shape. GGX's slope distribution has no finite variance, so for GGX the
// same sum is a heuristic fit.

/** s = 2/α² − 2 (the Phong–Beckmann correspondence of Walter et al., "Microfacet Models for
 * Refraction through Rough Surfaces", EGSR 2007).
 * @param {number} alpha
 */
export function exponentFromAlpha(alpha) {
  return 2 / (alpha * alpha) - 2;
}

/**
 * α = √(2/(s + 2)), the inverse of exponentFromAlpha.
 * @param {number} s
 */
export function alphaFromExponent(s) {
  return Math.sqrt(2 / (s + 2));
}

/**
 * Toksvig's variance from the stored length L = |N_a|: σ² = (1 − L)/L, i.e. L = 1/(1 + σ²)
 * (Toksvig, "Mipmapping Normal Maps", NVIDIA 2004). L ≥ 1 (8-bit noise, 2-channel
 * reconstruction) gives 0; L = 0 gives Infinity.
 * @param {number} L
 */
export function toksvigVariance(L) {
  if (L >= 1) return 0;
  if (!(L > 0)) return Infinity;
  return (1 - L) / L;
}

/**
 * f_t = 1/(1 + sσ²) = L/(L + s(1 − L)) (Hill, "Specular Showdown in the Wild West", 2011).
 * @param {number} L
 * @param {number} s
 */
export function toksvigFactor(L, s) {
  return 1 / (1 + s * toksvigVariance(L));
}

/**
 * Blinn-Phong: s' = f_t·s = s/(1 + sσ²) (Toksvig 2004, as quoted by Hill 2011).
 * @param {number} L
 * @param {number} s
 */
export function toksvigExponent(L, s) {
  return s * toksvigFactor(L, s);
}

/**
 * GGX/Beckmann form: α'² = (α² + 2σ²(1 − α²)) / (1 + 2σ²(1 − α²)) ≈ α² + 2σ² (derived:
 * equal to MJP's s = 2/α² − 2, α' = √(2/(f_t s + 2)) in TheRealMJP/SpecularAA's Mesh.hlsl and to
 * Unreal's ApplyCompositeTexture in TextureCompressorModule.cpp; both checked on a grid in
 * tests/unit/normals-lobes.test.js). It saturates at α' = 1 as σ² → ∞.
 * @param {number} L
 * @param {number} alpha
 */
export function toksvigAlpha(L, alpha) {
  const v = toksvigVariance(L);
  if (v === Infinity) return 1;
  const a2 = alpha * alpha;
  const k = 2 * v * (1 - a2);
  return Math.sqrt((a2 + k) / (1 + k));
}

/**
 * vMF concentration from the mean resultant length r: κ ≈ (3r − r³)/(1 − r²), the estimate
 * r(p − r²)/(1 − r²) with p = 3 of Banerjee, Dhillon, Ghosh, Sra, "Clustering on the Unit
 * Hypersphere using von Mises-Fisher Distributions", JMLR 6, 2005, as MJP's SpecularAA and
 * Filament's roughness-prefilter use it, with κ = 10000 for r ≥ 1.
 * @param {number} r
 */
export function vmfKappa(r) {
  if (r >= 1) return 10000;
  if (!(r > 0)) return 0;
  return (3 * r - r * r * r) / (1 - r * r);
}

/**
 * The exact mean length of a vMF lobe, r(κ) = coth κ − 1/κ (Banerjee et al. 2005's A_p(κ) for p = 3).
 * @param {number} kappa
 */
export function vmfMeanLength(kappa) {
  if (kappa === 0) return 0;
  return 1 / Math.tanh(kappa) - 1 / kappa;
}

/**
 * α' = √(α² + 2/κ) (MJP SpecularAA commit 0eee4b5, 2018, "2/κ" replacing "1/(2κ)"; Filament
 * roughness-prefilter). κ = 0 (r = 0) gives Infinity: no lobe at all.
 * @param {number} r
 * @param {number} alpha
 */
export function vmfAlpha(r, alpha) {
  const kappa = vmfKappa(r);
  return kappa === 0 ? Infinity : Math.sqrt(alpha * alpha + 2 / kappa);
}

/**
 * LEAN's slope covariance plus the base lobe: Σ = M − B Bᵀ + v₀ I with v₀ = α²/2, the per-axis
 * slope variance of a Beckmann lobe (D ∝ exp(−tan²θ/α²) is a Gaussian in slope, Walter et al.
 * 2007; and 1/s ≈ α²/2 for s = 2/α² − 2). Olano & Baker, "LEAN Mapping", I3D 2010, use v₀ = 1/s
 * for Blinn-Phong. Quantized moments can give a negative variance: each is clamped at 0 and |Σxy|
 * at √(ΣxxΣyy) (det Σ ≥ 0, as TheRealMJP/SpecularAA clamps it). Returns { sxx, syy, sxy, major, minor } with the eigenvalues major ≥ minor.
 * @param {number} bx
 * @param {number} by
 * @param {number} mxx
 * @param {number} myy
 * @param {number} mxy
 * @param {number} alpha
 */
export function leanCovariance(bx, by, mxx, myy, mxy, alpha) {
  const v0 = (alpha * alpha) / 2;
  const cxx = Math.max(0, mxx - bx * bx);
  const cyy = Math.max(0, myy - by * by);
  const lim = Math.sqrt(cxx * cyy);
  const cxy = Math.min(lim, Math.max(-lim, mxy - bx * by));
  const sxx = cxx + v0;
  const syy = cyy + v0;
  const half = 0.5 * (sxx + syy);
  const disc = Math.sqrt(0.25 * (sxx - syy) ** 2 + cxy * cxy);
  return { sxx, syy, sxy: cxy, major: half + disc, minor: half - disc };
}

/**
 * LEAN's lobe as roughness: per principal axis α_i = √(2λ_i) (inverting v = α²/2), and the
 * isotropic summary α' = √(λ_major + λ_minor) = √(α² + tr C), equal to CLEAN's (derived).
 * @param {number} bx
 * @param {number} by
 * @param {number} mxx
 * @param {number} myy
 * @param {number} mxy
 * @param {number} alpha
 */
export function leanAlpha(bx, by, mxx, myy, mxy, alpha) {
  const { major, minor } = leanCovariance(bx, by, mxx, myy, mxy, alpha);
  return { alpha: Math.sqrt(major + minor), alphaMajor: Math.sqrt(2 * major), alphaMinor: Math.sqrt(2 * minor) };
}

/**
 * CLEAN's variance σ² = M − (Bx² + By²), summed over both axes, clamped at 0 (Baker, GDC 2011).
 * @param {number} bx
 * @param {number} by
 * @param {number} m
 */
export function cleanVariance(bx, by, m) {
  return Math.max(0, m - bx * bx - by * by);
}

/**
 * CLEAN as roughness: per-axis v = σ²/2, so α'² = α² + 2v = α² + σ².
 * @param {number} bx
 * @param {number} by
 * @param {number} m
 * @param {number} alpha
 */
export function cleanAlpha(bx, by, m, alpha) {
  return Math.sqrt(alpha * alpha + cleanVariance(bx, by, m));
}

/**
 * z of a 2-channel normal: √(max(0, 1 − x² − y²)) (BC5/"XY" normals).
 * @param {number} x
 * @param {number} y
 */
export function reconstructZ(x, y) {
  return Math.sqrt(Math.max(0, 1 - x * x - y * y));
}
