// The uniforms of shaders/normalMaps.glsl (the GLSL twin of the procedural maps) for one map
// object from createNormalMap. Pure: no DOM, no WebGL.
import { createNormalMap } from './createNormalMap.js';
import { createValueNoise } from './createValueNoise.js';
import { degToRad } from './mapMath.js';

/** uMapKind of each map kind (the switch in mapSlope). */
export const MAP_KIND_INDEX = Object.freeze({ bumps: 0, grooves: 1, checker: 2, noise: 3, mixed: 4, flat: 5 });
const PROFILES = { v: 0, sine: 1 };
const DIRECTIONS = { u: 0, v: 1, diagonal: 2 };
// The shader keeps createBumps' default fill and createSlopeChecker's default azimuth as constants.
const SHADER_FILL = 0.8;
const SHADER_AZIMUTH_DEG = 45;
// Lattice periods and feature counts must be exact in float32 and fit an int shift (2^24).
const MAX_FEATURES = 2 ** 24;

function checkFill(fill) {
  if (fill !== SHADER_FILL) throw new RangeError(`the shader draws bumps with fill ${SHADER_FILL} only, got ${fill}`);
}

function checkAzimuth(azimuthDeg) {
  if (((azimuthDeg % 360) + 360) % 360 !== SHADER_AZIMUTH_DEG) {
    throw new RangeError(`the shader draws the checker at azimuth ${SHADER_AZIMUTH_DEG}° only, got ${azimuthDeg}°`);
  }
}

function checkFeatures(count, what) {
  if (count > MAX_FEATURES) throw new RangeError(`${what} ${count} per tile exceeds the shader's float32 limit 2^24`);
}

// Math.imul reads the seed mod 2^32 (ToInt32); the int uniform holds the same 32 bits. Beyond
// [−2^31, 2^32) seed + 7919·o would stop being exact in float64 before ToInt32.
function seedBits(seed) {
  if (!(seed >= -(2 ** 31) && seed < 2 ** 32)) throw new RangeError(`noise seed must be in [-2^31, 2^32), got ${seed}`);
  return seed | 0;
}

function noiseUniforms({ octaves, gain, amplitude, seed }) {
  return { uNoiseOctaves: octaves, uNoiseGain: gain, uNoiseAmplitude: amplitude, uNoiseSeed: seedBits(seed) };
}

/**
 * mapUniforms(map) → { uMapKind, uMapFreq, uMapAngle, uGrooveProfile, uGrooveDirection,
 * uNoiseOctaves, uNoiseGain, uNoiseAmplitude, uNoiseSeed, uMixedBlocks, uMixedEdgeAngle }:
 * always all eleven keys, angles in radians, those the kind does not read set to 0. The map's
 * params are re-validated (and missing ones defaulted) by its own factory; a RangeError is thrown
 * for a kind or parameter the shader cannot draw (bump fill ≠ 0.8, checker azimuth ≠ 45°, more
 * than 2^24 features per tile).
 */
export function mapUniforms(map) {
  const kind = map?.kind;
  const p = createNormalMap(kind, map?.params ?? {}).params;
  const out = {
    uMapKind: MAP_KIND_INDEX[kind], uMapFreq: 0, uMapAngle: 0, uGrooveProfile: 0, uGrooveDirection: 0,
    uNoiseOctaves: 0, uNoiseGain: 0, uNoiseAmplitude: 0, uNoiseSeed: 0, uMixedBlocks: 0, uMixedEdgeAngle: 0,
  };
  if (kind === 'flat') return out;
  out.uMapFreq = p.frequency;
  if (kind === 'bumps') {
    checkFill(p.fill);
    checkFeatures(p.frequency, 'bumps');
    out.uMapAngle = degToRad(p.edgeAngleDeg);
  } else if (kind === 'grooves') {
    checkFeatures(p.direction === 'diagonal' ? 2 * p.frequency : p.frequency, 'grooves'); // diagonal: f·u + f·v
    out.uMapAngle = degToRad(p.angleDeg);
    out.uGrooveProfile = PROFILES[p.profile];
    out.uGrooveDirection = DIRECTIONS[p.direction];
  } else if (kind === 'checker') {
    checkAzimuth(p.azimuthDeg);
    checkFeatures(p.frequency, 'checker cells');
    out.uMapAngle = degToRad(p.angleDeg);
  } else if (kind === 'noise') {
    checkFeatures(p.frequency * 2 ** (p.octaves - 1), 'noise lattice cells');
    Object.assign(out, noiseUniforms(p));
  } else {
    // createMixedMap's children: bumps and noise at f = blocks·frequency, V-grooves at 2f,
    // checker at 4f, noise with its factory's default octaves and gain.
    const f = p.blocks * p.frequency;
    checkFeatures(4 * f, 'mixed checker cells');
    const noise = createValueNoise({ frequency: f, amplitude: p.amplitude, seed: p.seed }).params;
    checkFeatures(f * 2 ** (noise.octaves - 1), 'noise lattice cells');
    Object.assign(out, noiseUniforms(noise));
    out.uMapFreq = f;
    out.uMapAngle = degToRad(p.angleDeg);
    out.uMixedBlocks = p.blocks;
    out.uMixedEdgeAngle = degToRad(p.edgeAngleDeg);
  }
  return out;
}
