import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { createNormalMap, MAP_KINDS } from '../../src/normals/createNormalMap.js';
import { createValueNoise } from '../../src/normals/createValueNoise.js';
import { MAP_KIND_INDEX, mapUniforms } from '../../src/normals/mapUniforms.js';

const deg = (d) => (d * Math.PI) / 180;
const KEYS = ['uMapKind', 'uMapFreq', 'uMapAngle', 'uGrooveProfile', 'uGrooveDirection', 'uNoiseOctaves', 'uNoiseGain',
  'uNoiseAmplitude', 'uNoiseSeed', 'uMixedBlocks', 'uMixedEdgeAngle'];

describe('mapUniforms: the uniforms of shaders/normalMaps.glsl for a map', () => {
  it('returns exactly the uniforms the shader chunk declares, for every kind', () => {
    const glsl = readFileSync('shaders/normalMaps.glsl', 'utf8');
    const declared = [...glsl.matchAll(/^uniform\s+(?:highp\s+)?\w+\s+(\w+);/gm)].map((m) => m[1]);
    expect(declared.sort()).toEqual([...KEYS].sort());
    for (const kind of MAP_KINDS) {
      const u = mapUniforms(createNormalMap(kind));
      expect(Object.keys(u).sort()).toEqual([...KEYS].sort());
      expect(u.uMapKind).toBe(MAP_KIND_INDEX[kind]);
      for (const value of Object.values(u)) expect(Number.isFinite(value)).toBe(true);
    }
    expect(new Set(Object.values(MAP_KIND_INDEX)).size).toBe(MAP_KINDS.length);
  });

  it('bumps, grooves, checker: frequency, angle in radians, groove profile and direction', () => {
    expect(mapUniforms(createNormalMap('bumps', { frequency: 12, edgeAngleDeg: 30 }))).toMatchObject({
      uMapKind: 0, uMapFreq: 12, uMapAngle: deg(30), uNoiseOctaves: 0, uMixedBlocks: 0,
    });
    const sine = mapUniforms(createNormalMap('grooves', { frequency: 8, angleDeg: 25, profile: 'sine', direction: 'v' }));
    expect(sine).toMatchObject({ uMapKind: 1, uMapFreq: 8, uMapAngle: deg(25), uGrooveProfile: 1, uGrooveDirection: 1 });
    expect(mapUniforms(createNormalMap('grooves', { direction: 'diagonal' }))).toMatchObject({ uGrooveProfile: 0, uGrooveDirection: 2 });
    expect(mapUniforms(createNormalMap('grooves'))).toMatchObject({ uMapFreq: 16, uMapAngle: deg(20), uGrooveDirection: 0 });
    expect(mapUniforms(createNormalMap('checker', { frequency: 6, angleDeg: 10 }))).toMatchObject({ uMapKind: 2, uMapFreq: 6, uMapAngle: deg(10) });
    expect(mapUniforms(createNormalMap('checker', { azimuthDeg: -315 })).uMapKind).toBe(2); // the same azimuth as 45°
  });

  it('noise: octaves, gain, amplitude and the seed as int32', () => {
    const u = mapUniforms(createNormalMap('noise', { frequency: 4, octaves: 5, gain: 0.6, amplitude: 0.2, seed: 42 }));
    expect(u).toMatchObject({ uMapKind: 3, uMapFreq: 4, uNoiseOctaves: 5, uNoiseGain: 0.6, uNoiseAmplitude: 0.2, uNoiseSeed: 42, uMapAngle: 0 });
    expect(mapUniforms(createNormalMap('noise', { seed: -7 })).uNoiseSeed).toBe(-7);
    expect(mapUniforms(createNormalMap('noise', { seed: 2 ** 32 - 1 })).uNoiseSeed).toBe(-1);
    // The JS hash itself reads the seed mod 2^32, so the int32 uniform is the same map.
    const a = createValueNoise({ seed: 2 ** 32 - 1 }).slopeAt(0.3, 0.7);
    const b = createValueNoise({ seed: -1 }).slopeAt(0.3, 0.7);
    expect(a).toEqual(b);
    expect(createValueNoise({ seed: 2 }).slopeAt(0.3, 0.7)).not.toEqual(b);
  });

  it("mixed: f = blocks × frequency, the bumps' edge angle, the noise child's default octaves and gain", () => {
    const map = createNormalMap('mixed', { blocks: 3, frequency: 2, angleDeg: 15, edgeAngleDeg: 40, amplitude: 0.05, seed: 9 });
    expect(mapUniforms(map)).toEqual({
      uMapKind: 4, uMapFreq: 6, uMapAngle: deg(15), uGrooveProfile: 0, uGrooveDirection: 0, uNoiseOctaves: 3,
      uNoiseGain: 0.5, uNoiseAmplitude: 0.05, uNoiseSeed: 9, uMixedBlocks: 3, uMixedEdgeAngle: deg(40),
    });
  });

  it('fills defaults for missing params exactly as the factories do', () => {
    for (const kind of MAP_KINDS) expect(mapUniforms({ kind })).toEqual(mapUniforms(createNormalMap(kind)));
    expect(mapUniforms({ kind: 'noise', params: { seed: 3 } })).toEqual(mapUniforms(createNormalMap('noise', { seed: 3 })));
  });

  it('throws a RangeError for what the shader cannot draw or the factory rejects', () => {
    expect(() => mapUniforms(createNormalMap('bumps', { fill: 0.5 }))).toThrow(RangeError);
    expect(() => mapUniforms(createNormalMap('checker', { azimuthDeg: 30 }))).toThrow(RangeError);
    expect(() => mapUniforms(createNormalMap('checker', { azimuthDeg: 0 }))).toThrow(/azimuth/);
    expect(() => mapUniforms({ kind: 'grooves', params: { profile: 'square' } })).toThrow(RangeError);
    expect(() => mapUniforms({ kind: 'grooves', params: { direction: 'w' } })).toThrow(RangeError);
    expect(() => mapUniforms({ kind: 'marble' })).toThrow(RangeError);
    expect(() => mapUniforms(undefined)).toThrow(RangeError);
    expect(() => mapUniforms(createNormalMap('noise', { seed: 2 ** 32 }))).toThrow(/seed/);
    expect(() => mapUniforms(createNormalMap('noise', { seed: -(2 ** 31) - 1 }))).toThrow(RangeError);
    expect(() => mapUniforms(createNormalMap('noise', { frequency: 2 ** 22, octaves: 4 }))).toThrow(/2\^24/);
    expect(() => mapUniforms(createNormalMap('mixed', { blocks: 2 ** 12, frequency: 2 ** 11 }))).toThrow(RangeError);
    expect(mapUniforms(createNormalMap('noise', { frequency: 2 ** 21, octaves: 4 })).uMapFreq).toBe(2 ** 21);
  });
});
