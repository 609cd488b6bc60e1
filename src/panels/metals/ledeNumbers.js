// The numbers the panel's lede states (locales/en.json, panels → metals.lede), each in the words
// around it, from the metals' data and the curves the panel plots: tests/unit/teachingText.test.js
// fails where the lede says other numbers, or more. Not part of the panel's module (nothing imports it).
import { metalF0, metals } from '../../optics/materials.js';
import { fixed } from '../../ui/format.js';
import { metalCurves, metalCurveStats } from './physics.js';

/** @returns {string[]} */
export function ledeNumbers() {
  const f0 = metals.flatMap((m) => metalF0(m));
  // Towards grazing the deepest dip below F0 of any metal's channel, and where it is.
  const channels = metals.flatMap((m) => metalCurveStats(metalCurves(m), m).map((s) => ({ metal: m.id, ...s })));
  const deepest = channels.reduce((a, b) => (b.dip > a.dip ? b : a));
  return [
    `from ${fixed(Math.min(...f0), 2)} to ${fixed(Math.max(...f0), 2)} of the light per channel`,
    `(${deepest.metal}'s ${deepest.channel} by ${fixed(deepest.dip, 2)}, near ${fixed(deepest.minimum.theta, 0)}°;`,
  ];
}
