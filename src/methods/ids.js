// The ids of the methods, scenes and display budgets as plain lists: what the panels' schemas need
// (their options are ids; the words are the catalogue's), without the method table, the scenes'
// references or the advisor, which come with the panels that compute. tests/unit/methods.test.js
// holds these lists equal to the tables they name.

/** The dielectric methods of methods.js, in table order. */
export const DIELECTRIC_METHOD_IDS = Object.freeze([
  'exact-cg', 'exact-cg-literal', 'exact-sp', 'schlick-pow', 'schlick-mul', 'schlick-tir', 'schlick-exp2',
]);

/** The scenes of scenes.js, in order. */
export const SCENE_IDS = Object.freeze(['plastic', 'glass-inside', 'ice-water', 'metal', 'phone-mediump']);

/** The display budgets of displayBudgets.js, strictest first, and the one a panel starts with. */
export const BUDGET_IDS = Object.freeze(['invisible', 'one-code', 'one-percent', 'acceptable', 'ten-percent']);
export const DEFAULT_BUDGET = 'invisible';
