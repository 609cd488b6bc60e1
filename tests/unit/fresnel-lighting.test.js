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
