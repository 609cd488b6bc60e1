// One colour and dash per technique, for every picture of the panel that tells them apart (the
// RMSE-by-level plot, the texel inspector): theme colours from styles.css, so both follow the theme.
// The two that lose the spread are warm and grey, renormalized dashed.
export const TECHNIQUE_STYLES = Object.freeze({
  naive: { stroke: '--c-red' },
  renormalized: { stroke: '--c-marker', dash: [10, 6] },
  toksvig: { stroke: '--c-schlick' },
  lean: { stroke: '--c-blue' },
  clean: { stroke: '--c-error', dash: [4, 4] },
  vmf: { stroke: '--c-green' },
});
