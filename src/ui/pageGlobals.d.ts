// What the lab adds to the window, for the modules that are type-checked.

// theme.js dispatches `fresnel-lab:theme` with the page's theme whenever it changes (plots and
// panels' frames follow it).
interface WindowEventMap {
  'fresnel-lab:theme': CustomEvent<import('./theme.js').Theme>;
}

interface Window {
  /** Each page's hook for the browser tests and the benchmark: what it holds is the page's own. */
  fresnelLab?: object;
}
