// The audio trace of a dielectric panel's R(θ) plot (createAudioTrace.js): the curves it can
// follow, each evaluated exactly by the optics core at the cursor's θ (never read off the
// plotted samples), and the index pair's Brewster and critical angles.
import { cosDeg, DEG } from '../../optics/angles.js';
import { brewsterAngle, criticalAngle, fresnelExact, fresnelPolarized, fresnelSchlick, fresnelSchlickTIR } from '../../optics/fresnel.js';
import { createAudioTrace } from '../../ui/createAudioTrace.js';

const CURVES = {
  exact: ['Exact R', fresnelExact],
  schlick: ['Schlick', fresnelSchlick],
  schlickT: ['Schlick on cos θt', fresnelSchlickTIR],
  s: ['Rs', (c, nI, nT) => fresnelPolarized(c, nI, nT).s],
  p: ['Rp', (c, nI, nT) => fresnelPolarized(c, nI, nT).p],
};

/** Degrees: the Brewster angle atan(n_t/n_i) and the critical angle asin(n_t/n_i) (null when n_i ≤ n_t). */
export function dielectricLandmarks(nI, nT) {
  const critical = criticalAngle(nI, nT);
  return { brewster: brewsterAngle(nI, nT) / DEG, critical: critical === null ? null : critical / DEG };
}

/**
 * A trace under `plotHost` of the curves named by `keys` (exact, schlick, schlickT, s, p) with
 * the indices `indices()` gives now ({ nI, nT }); labels: the plot's own names of them, where they differ.
 * @param {HTMLElement} plotHost
 * @param {{ setCursor: (deg: number | null, label?: string) => void }} plot
 * @param {() => { nI: number, nT: number }} indices
 * @param {(keyof typeof CURVES)[]} keys
 * @param {Partial<Record<keyof typeof CURVES, string>>} [labels]
 */
export function addDielectricTrace(plotHost, plot, indices, keys = ['exact'], labels = {}) {
  return createAudioTrace(plotHost, {
    plot,
    curves: () => {
      const { nI, nT } = indices();
      return keys.map((key) => {
        const [label, f] = CURVES[key];
        return { label: labels[key] ?? label, at: (deg) => f(cosDeg(deg), nI, nT) };
      });
    },
    landmarks: () => {
      const { nI, nT } = indices();
      return dielectricLandmarks(nI, nT);
    },
  });
}
