// The mip-chain techniques the normal-mips panel compares, by id, in the order it shows them: a list
// of its own so that the panel's schema needs nothing of the layouts (techniqueLayout.js).
export const TECHNIQUES = Object.freeze(['naive', 'renormalized', 'toksvig', 'lean', 'clean', 'vmf']);
