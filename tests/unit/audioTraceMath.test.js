// The audio trace's mapping, checked against values worked out by hand: pitch two octaves over
// R in [0, 1], the cursor's steps on a 0.1° grid, and the landmarks each move passes.
import { describe, expect, it } from 'vitest';
import { cuesBetween, inTir, pitchHz, stepCursor, sweepPlan, traceReadout } from '../../src/ui/audioTraceMath.js';

describe('pitchHz', () => {
  it('maps R = 0, 0.5, 1 to 220, 440, 880 Hz, clamps, and has no pitch for NaN', () => {
    expect(pitchHz(0)).toBe(220);
    expect(pitchHz(0.5)).toBeCloseTo(440, 9);
    expect(pitchHz(1)).toBe(880);
    expect(pitchHz(1.2)).toBe(880);
    expect(pitchHz(-0.1)).toBe(220);
    expect(pitchHz(Number.NaN)).toBeNull();
    // a whole tone (2^(2/12)) per twelfth of R
    expect(pitchHz(1 / 12) / pitchHz(0)).toBeCloseTo(2 ** (1 / 6), 12);
  });
});

describe('stepCursor', () => {
  it('steps 1°, 0.1° with Shift, 10° with the Page keys, and stops at the ends', () => {
    expect(stepCursor(0, 'ArrowRight')).toBe(1);
    expect(stepCursor(1, 'ArrowLeft')).toBe(0);
    expect(stepCursor(0, 'ArrowLeft')).toBe(0);
    expect(stepCursor(56, 'ArrowRight', true)).toBe(56.1);
    expect(stepCursor(85, 'PageUp')).toBe(90);
    expect(stepCursor(5, 'PageDown')).toBe(0);
    expect(stepCursor(33.3, 'Home')).toBe(0);
    expect(stepCursor(33.3, 'End')).toBe(90);
    expect(stepCursor(10, 'a')).toBeNull();
  });
  it('never drifts off the 0.1° grid', () => {
    let deg = 0;
    for (let i = 0; i < 300; i += 1) deg = stepCursor(deg, 'ArrowRight', true);
    expect(deg).toBe(30);
  });
});

describe('cuesBetween', () => {
  const glassToAir = { brewster: 33.69, critical: 41.81 };
  it('meets each landmark a move passes, in either direction', () => {
    expect(cuesBetween(33, 34, glassToAir)).toEqual(['brewster']);
    expect(cuesBetween(34, 33, glassToAir)).toEqual(['brewster']);
    expect(cuesBetween(30, 50, glassToAir)).toEqual(['brewster', 'critical']);
    expect(cuesBetween(42, 43, glassToAir)).toEqual([]);
    expect(cuesBetween(0, 1, { brewster: 56.31, critical: null })).toEqual([]);
  });
  it('does not meet again the landmark it starts on', () => {
    expect(cuesBetween(41.81, 41.9, glassToAir)).toEqual([]);
    expect(cuesBetween(41.81, 41.81, glassToAir)).toEqual(['critical']);
  });
  it('knows the total-internal-reflection range: at and past the critical angle', () => {
    expect(inTir(41.81, 41.81)).toBe(true);
    expect(inTir(41.8, 41.81)).toBe(false);
    expect(inTir(89, null)).toBe(false);
  });
});

describe('traceReadout and sweepPlan', () => {
  it('says θ, the value and the landmark in words', () => {
    expect(traceReadout(56.3, [{ label: 'Rp', value: 0.0000012 }], { brewster: 56.31, critical: null, cues: ['brewster'] }))
      .toBe('θ 56.3°: Rp 0.0000. Passed the Brewster angle, 56.31°: Rp is 0 there.');
    expect(traceReadout(60, [{ label: 'Exact R', value: 1 }], { brewster: 33.69, critical: 41.81 }))
      .toBe('θ 60.0°: Exact R 1.0000. Total internal reflection: R = 1.');
    expect(traceReadout(42, [{ label: 'Exact R', value: 1 }], { brewster: 33.69, critical: 41.81, cues: ['critical'] }))
      .toMatch(/Passed the critical angle, 41\.81°: total internal reflection above it\.$/);
  });
  it('plans a sweep: a pitch per half degree, the TIR range and the landmarks at their times', () => {
    const plan = sweepPlan((deg) => (deg >= 45 ? 1 : 0), { brewster: 30, critical: 45 }, { seconds: 3 });
    expect(plan.points).toHaveLength(181);
    expect(plan.points[0]).toEqual({ deg: 0, t: 0, hz: 220, tir: false });
    expect(plan.points[90]).toEqual({ deg: 45, t: 1.5, hz: 880, tir: true });
    expect(plan.cues).toEqual([{ kind: 'brewster', deg: 30, t: 1 }, { kind: 'critical', deg: 45, t: 1.5 }]);
  });
});
