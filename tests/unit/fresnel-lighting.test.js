import { describe, expect, it } from 'vitest';
import { FRAGMENT, MIX_GLSL } from '../../src/panels/fresnel-lighting/index.js';
import fragmentSource from '../../src/panels/fresnel-lighting/fresnel-lighting.frag.glsl?raw';
import { STAGE_CAMERA, offsetAtAngle } from '../../src/panels/shared/createTwinStage.js';

const DEG = Math.PI / 180;

describe('fresnel-lighting GLSL', () => {
  const shown = MIX_GLSL; // what the panel displays
  it('the lines shown are compiled verbatim into the shader', () => {
    expect(fragmentSource).toMatch(/^\s*#include <fresnel-lighting-mix>\s*$/m);
    expect(FRAGMENT).toContain(shown);
  });
  it('shows the lecture mix with exact and Schlick F and the constant weight', () => {
    expect(shown).toContain('vec3 kExact = mix(kd, ks, fresnelExact(dot(N, V), 1.0, n));');
    expect(shown).toContain('vec3 kSchlick = mix(kd, ks, fresnelSchlick(dot(N, V), 1.0, n));');
    expect(shown).toContain('vec3 kConstant = mix(kd, ks, w);');
  });
});

describe('two-sphere stage geometry', () => {
  // Cast the ray through a midline offset the way shaders/twinStage.glsl does
  // (camera on the z axis here: the angle at the sphere does not depend on the elevation).
  function viewAngleAt(offset) {
    const { distance, fovDeg } = STAGE_CAMERA;
    const focal = 1 / Math.tan((fovDeg * DEG) / 2);
    const len = Math.hypot(focal, offset);
    const dir = [offset / len, 0, -focal / len];
    const eye = [0, 0, distance];
    const b = dir[0] * eye[0] + dir[2] * eye[2];
    const h = b * b - (distance * distance - 1);
    if (h < 0) return null;
    const t = -b - Math.sqrt(h);
    const normal = [eye[0] + t * dir[0], eye[1], eye[2] + t * dir[2]];
    const cos = -(normal[0] * dir[0] + normal[2] * dir[2]);
    return Math.acos(Math.min(1, cos)) / DEG;
  }

  it('maps θ to the pixel offset where the ray sees that angle', () => {
    expect(offsetAtAngle(0)).toBe(0);
    for (const theta of [10, 45, 70, 80, 85, 89]) expect(viewAngleAt(offsetAtAngle(theta))).toBeCloseTo(theta, 6);
  });
  it('keeps the spheres inside their halves with sky around them', () => {
    const edge = offsetAtAngle(90);
    expect(edge).toBeLessThan(0.9); // of half the canvas height: a margin above and below
    expect(viewAngleAt(edge * 1.01)).toBeNull();
  });
});

describe('the layered coat beside the lecture\'s mix', async () => {
  const { coatConstants, diffuseShares, diffuseSharesRgb, layeredCoat, lectureCoat } = await import(
    '../../src/panels/fresnel-lighting/physics.js');
  const { hemisphericalReflectance } = await import('../../src/optics/diffuseFresnel.js');
  const { fresnelExact } = await import('../../src/optics/fresnel.js');
  it('diffuse reflectance: 0.60 under a coat of 1.5, 0.09 from the air, and 1 − r_in = (1 − r_out)/n²', () => {
    // Egan & Hilgeman's fit, F_dr(η) = −1.440/η² + 0.710/η + 0.668 + 0.0636η (Jensen et al., SIGGRAPH 2001, eq. 5).
    const fit = (eta) => -1.44 / eta ** 2 + 0.71 / eta + 0.668 + 0.0636 * eta;
    for (const n of [1.33, 1.5, 1.7]) {
      const inside = hemisphericalReflectance(n, 1);
      const outside = hemisphericalReflectance(1, n);
      expect(Math.abs(inside - fit(n)), `${n}`).toBeLessThan(0.006);
      expect(1 - inside).toBeCloseTo((1 - outside) / (n * n), 12);
    }
    expect(hemisphericalReflectance(1.5, 1)).toBeCloseTo(0.5963, 4);
    expect(hemisphericalReflectance(1.5, 1.5)).toBe(0);
    // By brute force: a 20,000-step midpoint sum of 2R(μ)μ.
    let sum = 0;
    for (let i = 0; i < 20000; i += 1) { const mu = (i + 0.5) / 20000; sum += 2 * fresnelExact(mu, 1.5, 1) * mu / 20000; }
    expect(hemisphericalReflectance(1.5, 1)).toBeCloseTo(sum, 5);
  });
  it('with no coat (n = 1) the layered model is the bare base, as the lecture\'s is', () => {
    const { ri, re } = coatConstants(1);
    expect(ri).toBe(0);
    expect(re).toBe(0);
    const v = { albedo: 0.4, sun: 0.7, sky: 0.2, ks: 0.9, cosV: 0.6, cosL: 0.7, n: 1, ri, re };
    expect(layeredCoat(v)).toBeCloseTo(0.4 * (0.7 + 0.2), 14);
    expect(lectureCoat({ kd: 0.4 * 0.9, ks: 0.9, cosV: 0.6, n: 1 })).toBeCloseTo(0.36, 14);
  });
  it('the default kd #a3241c lets out 0.524, 0.414, 0.412 per channel, 0.51 of its luminance (not 0.43 of a grey)', () => {
    // Independent arithmetic: sRGB decode (IEC 61966-2-1), the share (1 − R0)²/(n²(1 − a·ri)) per channel, Rec. 709 weights.
    const decode = (v) => (v <= 0.04045 ? v / 12.92 : ((v + 0.055) / 1.055) ** 2.4);
    const kd = [0xa3, 0x24, 0x1c].map((b) => decode(b / 255));
    const ri = hemisphericalReflectance(1.5, 1);
    const share = (a) => ((1 - 0.04) ** 2) / (2.25 * (1 - a * ri));
    const w = [0.2126, 0.7152, 0.0722];
    const Y = (rgb) => rgb.reduce((sum, x, i) => sum + w[i] * x, 0);
    const s = diffuseSharesRgb({ kd, cosV: 1, cosL: 1, n: 1.5, ri });
    kd.forEach((a, i) => expect(s.layered[i]).toBeCloseTo(share(a), 12));
    expect(s.layered.map((x) => x.toFixed(3))).toEqual(['0.524', '0.414', '0.412']);
    expect(s.layeredLuminance).toBeCloseTo(Y(kd.map((a) => a * share(a))) / Y(kd), 12);
    expect(s.layeredLuminance.toFixed(2)).toBe('0.51');
    // Feeding the luminance of kd through the nonlinear term gives the old, wrong 0.43.
    expect(share(Y(kd)).toFixed(2)).toBe('0.43');
  });
  it('a coated base that is not near white lets out less of its diffuse light than the lecture\'s mix; energy is kept', () => {
    const { ri } = coatConstants(1.5);
    // Light bouncing under the coat (1/(1 − albedo·ri)) makes up for the losses only on a near-white base.
    expect(diffuseShares({ albedo: 1, cosV: 1, cosL: 1, n: 1.5, ri }).layered).toBeGreaterThan(0.96);
    for (const albedo of [0, 0.2, 0.5, 0.7]) {
      for (const cosV of [1, 0.5, 0.1]) {
        const s = diffuseShares({ albedo, cosV, cosL: 1, n: 1.5, ri });
        expect(s.layered).toBeLessThan(s.lecture);
        expect(s.layered).toBeGreaterThan(0);
      }
    }
    // Head-on under an overhead sun, base albedo 0.5: (1 − 0.04)² / (2.25 (1 − 0.5·0.5963)).
    const s = diffuseShares({ albedo: 0.5, cosV: 1, cosL: 1, n: 1.5, ri });
    expect(s.layered).toBeCloseTo((0.96 * 0.96) / (2.25 * (1 - 0.5 * hemisphericalReflectance(1.5, 1))), 12);
    expect(s.lecture).toBeCloseTo(0.96, 12);
    // Energy: the coated white base under a white sky reflects at most what arrives (albedo 1: all of it).
    const { re } = coatConstants(1.5);
    let out = 0;
    const N = 2000;
    for (let i = 0; i < N; i += 1) {
      const mu = (i + 0.5) / N;
      const fV = fresnelExact(mu, 1, 1.5);
      out += 2 * mu * (layeredCoat({ albedo: 1, sun: 0, sky: 1, ks: 0, cosV: mu, cosL: 1, n: 1.5, ri, re }) + fV) / N;
    }
    expect(out).toBeCloseTo(1, 3); // sky in = diffuse out + mirrored sky (a white sky is uniform)
  });
  it('the GLSL shows the layered lines the model twins', () => {
    expect(MIX_GLSL).toContain('vec3 kLayered = fV * ks + (1.0 - fV) / (n * n)');
    expect(MIX_GLSL).toContain('* albedo * ((1.0 - fresnelExact(cosL, 1.0, n)) * sun + (1.0 - re) * sky) / (1.0 - albedo * ri);');
  });
});
