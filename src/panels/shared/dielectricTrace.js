// The audio trace of a dielectric panel's R(θ) plot (createAudioTrace.js): the curves it can
// follow, each evaluated exactly by the optics core at the cursor's θ (never read off the
// plotted samples), and the index pair's Brewster and critical angles.
import { cosDeg, DEG } from '../../optics/angles.js';
import { brewsterAngle, criticalAngle, fresnelExact, fresnelPolarized, fresnelSchlick, fresnelSchlickTIR } from '../../optics/fresnel.js';
import { createAudioTrace } from '../../ui/createAudioTrace.js';
import english from 'virtual:messages/en/panelsShared';
import { messages } from '../../i18n/messages.js';

const t = messages('panelsShared', english);

// Each curve's spoken name (the catalogue's key) and its function.
const CURVES = {
  exact: ['traceExact', fresnelExact],
  schlick: ['traceSchlick', fresnelSchlick],
  schlickT: ['traceSchlickT', fresnelSchlickTIR],
  s: ['traceS', (c, nI, nT) => fresnelPolarized(c, nI, nT).s],
  p: ['traceP', (c, nI, nT) => fresnelPolarized(c, nI, nT).p],
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
        const [word, f] = CURVES[key];
        return { label: labels[key] ?? t(word), at: (deg) => f(cosDeg(deg), nI, nT) };
      });
    },
    landmarks: () => {
      const { nI, nT } = indices();
      return dielectricLandmarks(nI, nT);
    },
  });
}
