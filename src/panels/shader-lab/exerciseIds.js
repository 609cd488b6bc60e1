// The exercises' ids, and the longest code taken: what the page needs for the panel's schema
// before the panel itself (exercises.js holds the criteria and the reference answers; the titles
// are the catalogue's, the names of the exercise control's options).
export const EXERCISE_IDS = Object.freeze(['schlick', 'exact', 'tir', 'safe', 'mediump', 'gold']);

export const MAX_CODE = 6000;
