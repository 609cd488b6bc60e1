// The exercises' ids and titles, and the longest code taken: what the page needs for the panel's
// schema before the panel itself (exercises.js holds the criteria and the reference answers).
export const EXERCISE_TITLES = Object.freeze({
  schlick: 'Write Schlick’s approximation',
  exact: 'Write the exact c/g form',
  tir: 'Make it correct under total internal reflection',
  safe: 'Make it safe for cos θ outside [0, 1]',
  mediump: 'Keep it accurate in mediump near the critical angle',
  gold: 'The conductor form, for gold',
});

export const MAX_CODE = 6000;
