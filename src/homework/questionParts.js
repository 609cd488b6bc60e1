// What the question lists share: the indices and angles parameters are drawn from, and how the
// explanations print numbers.

export const INDICES = Object.freeze([1.33, 1.45, 1.5, 1.6, 1.75, 2.0, 2.42]);
export const ANGLES = Object.freeze([30, 40, 45, 50, 55, 60, 65, 70, 75, 80]);
export const fixed = (x, d) => x.toFixed(d);
