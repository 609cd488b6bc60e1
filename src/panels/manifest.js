// @ts-check
// The panel manifest: every panel of the lecture, in the lecture's order, with what the page needs
// to know before the panel's code loads. The lecture page's sections and the places they keep
// (vite.config.js writes them into index.html and src/panelPlaces.css), the embed page and the
// tests all come from this list or are checked against it. Plain data and pure functions, whose one
// import has no imports of its own, so Node (the build, the unit tests) reads it too.
//
// A panel is the folder src/panels/<id>/ with its parameters in schema.js and its module in index.js
// (the same schema and mount; see src/host/panelContract.js). Adding a panel is adding its folder
// and one entry here (docs/panels.md).
import { escapeHtml } from '../ui/escapeHtml.js';

/**
 * A panel's place on the lecture page before its module arrives, in px, per layout (PLACE_LAYOUTS):
 * about 92 % of the panel's smallest mounted height over the window widths of that layout (measured
 * in Chromium), since larger type in projector mode only makes a panel taller. The browser tests
 * keep each one under the mounted height and above 40 % of it.
 * @typedef {object} PanelPlace
 * @property {number} narrow        one column: windows up to 1000 px wide (styles.css)
 * @property {number} wide          two columns, from 1001 px
 * @property {number} widest        from 1450 px
 */

/**
 * A panel's words are in the message catalogue (locales/en.json, namespace "panels"): `<id>.title`
 * (plain text: the embed heading, window titles, the controls' title), `<id>.titleHtml` where the
 * lecture page's heading needs markup (subscripts), `<id>.lede` (the paragraph under the heading,
 * with markup) and `<id>.cite` (where in the lecture, or beyond it, the concept comes from);
 * src/panels/panelText.js reads them in the page's language.
 * @typedef {object} PanelEntry
 * @property {string} id            fixed: URLs and embeds depend on it
 * @property {boolean} webgl        holds a WebGL context while mounted (counted against the budget)
 * @property {boolean} [webglAtTimes] webgl false, but it opens a context for a while (a measurement,
 *                                  a read-back): a deck never loads it off screen (src/lecture/deckSlides.js)
 * @property {string|null} material the parameter the page-wide material sets (its n), or null
 * @property {string} [materialSelect] instead: a parameter that takes the material's id
 * @property {boolean} [hero]       the first, large panel: it owns the short URL keys (?nT=…)
 * @property {string} [animates]    the boolean parameter that runs its animation (off: it draws only on change)
 * @property {PanelPlace} place     its place on the lecture page before it mounts, so that mounting moves nothing
 */

/** @type {readonly PanelEntry[]} */
export const PANELS = Object.freeze([
  {
    id: 'spheres',
    hero: true,
    webgl: true,
    material: 'nT',
    place: { narrow: 1370, wide: 810, widest: 860 },
  },
  {
    id: 'normal-mips',
    webgl: true,
    material: null,
    place: { narrow: 2790, wide: 1900, widest: 1950 },
  },
  {
    id: 'asphalt',
    webgl: true,
    material: 'nT',
    place: { narrow: 1290, wide: 890, widest: 950 },
  },
  {
    id: 'changing-specular',
    webgl: true,
    material: 'nT',
    place: { narrow: 1200, wide: 850, widest: 860 },
  },
  {
    id: 'reflect-refract',
    webgl: true,
    material: 'nT',
    place: { narrow: 1360, wide: 990, widest: 1010 },
  },
  {
    id: 'refraction-waves',
    webgl: true,
    material: 'nT',
    animates: 'play',
    place: { narrow: 1180, wide: 780, widest: 880 },
  },
  {
    id: 'angle-ratio',
    webgl: false,
    material: 'nT',
    place: { narrow: 1140, wide: 890, widest: 880 },
  },
  {
    id: 'refractive-index',
    webgl: false,
    material: null,
    materialSelect: 'selected',
    place: { narrow: 1650, wide: 1330, widest: 990 },
  },
  {
    id: 'polarization',
    webgl: false,
    material: 'nT',
    place: { narrow: 990, wide: 690, widest: 630 },
  },
  {
    id: 'exact-fresnel',
    webgl: false,
    material: 'nT',
    place: { narrow: 1650, wide: 1380, widest: 780 },
  },
  {
    id: 'schlick',
    webgl: false,
    material: 'nT',
    place: { narrow: 1060, wide: 820, widest: 760 },
  },
  {
    id: 'r0-derivation',
    webgl: false,
    material: 'nT',
    place: { narrow: 1430, wide: 1230, widest: 1210 },
  },
  {
    id: 'fresnel-lighting',
    webgl: true,
    material: 'nT',
    place: { narrow: 1860, wide: 1450, widest: 1450 },
  },
  {
    id: 'metals',
    webgl: true,
    material: 'nT',
    place: { narrow: 1930, wide: 1640, widest: 1640 },
  },
  {
    id: 'speed-accuracy',
    webgl: false, // the chart is 2D
    webglAtTimes: true, // contexts live while a benchmark or a read-back runs
    material: null,
    place: { narrow: 1880, wide: 1530, widest: 1060 },
  },
  {
    id: 'stability',
    webgl: true,
    material: null,
    place: { narrow: 1090, wide: 870, widest: 870 },
  },
  {
    id: 'shader-lab',
    webgl: true,
    material: null,
    place: { narrow: 1670, wide: 1470, widest: 1480 },
  },
]);

/** Panel ids in lecture order. */
export const PANEL_IDS = Object.freeze(PANELS.map((p) => p.id));

/**
 * The manifest entry of a panel id, or undefined.
 * @param {string} id
 */
export function panelEntry(id) {
  return PANELS.find((p) => p.id === id);
}

/**
 * Whether a panel may hold a WebGL context: all the while it is mounted, or at times.
 * @param {PanelEntry} entry
 */
export const mayHoldContext = (entry) => entry.webgl || entry.webglAtTimes === true;

/**
 * URL key prefix of a panel on the lecture page: the hero owns the short keys.
 * @param {string} id
 */
export function lecturePrefix(id) {
  return panelEntry(id)?.hero ? '' : `${id}.`;
}

/**
 * The lecture page's <section> for a panel: heading, lede with its citation, and the mount point.
 * text: the panel's words ({ title, titleHtml?, lede, cite }, markup as the catalogue has it).
 * @param {PanelEntry} entry
 * @param {{ title: string, titleHtml?: string, lede: string, cite: string }} text
 */
export function sectionHtml(entry, text) {
  const heading = text.titleHtml ?? escapeHtml(text.title);
  return `<section data-panel="${entry.id}" id="${entry.id}" class="panel${entry.hero ? ' hero' : ''}" tabindex="-1" `
    + `aria-labelledby="${entry.id}-title">
      <h2 id="${entry.id}-title">${heading}</h2>
      <p class="lede">
        <span class="lede-text">${text.lede.trim()}</span>
        <span class="cite">(${text.cite})</span>
      </p>
      <div class="panel-mount"></div>
    </section>`;
}

/**
 * A panel's words from a catalogue's "panels" namespace (the English one, read from JSON).
 * @param {Record<string, string>} panels
 * @param {string} id
 * @returns {{ title?: string, titleHtml?: string, lede?: string, cite?: string }}
 */
export function panelTextFrom(panels, id) {
  /** @param {string} key */
  const at = (key) => (Object.hasOwn(panels, `${id}.${key}`) ? panels[`${id}.${key}`] : undefined);
  return { title: at('title'), titleHtml: at('titleHtml'), lede: at('lede'), cite: at('cite') };
}

/** Where the lecture page's sections go in index.html. */
export const SECTIONS_MARKER = '<!-- panel sections: written at build time from src/panels/manifest.js -->';

/**
 * The media query of each layout of a PanelPlace ('' for every window), narrowest first.
 * @type {Readonly<Record<keyof PanelPlace, string>>}
 */
export const PLACE_LAYOUTS = Object.freeze({ narrow: '', wide: '(min-width: 1001px)', widest: '(min-width: 1450px)' });

/** PLACE_LAYOUTS as [layout, media] pairs, narrowest first (Object.entries would forget the keys' type). */
export const placeLayouts = () => /** @type {[keyof PanelPlace, string][]} */ (Object.entries(PLACE_LAYOUTS));

/** Where the rules that keep each panel's place go in src/panelPlaces.css. */
export const PLACES_MARKER = '/* panel places: written at build time from src/panels/manifest.js */';

/**
 * The CSS that keeps each panel's place on the lecture page before it mounts, from the entries'
 * `place`: the page reserves it before any script runs, under the page's style-src 'self'.
 * @param {readonly PanelEntry[]} [panels]
 */
export function placesCss(panels = PANELS) {
  return placeLayouts().map(([layout, media]) => {
    const rules = panels.map((p) => `#${p.id} > .panel-mount { min-height: ${p.place[layout]}px; }`);
    return media ? `@media ${media} {\n  ${rules.join('\n  ')}\n}` : rules.join('\n');
  }).join('\n');
}

/**
 * What is wrong between the manifest, the panels' files (`files`: each index.js and schema.js
 * under src/panels, as `<folder>/<file>`), their words (`panelWords`: the English catalogue's
 * "panels" namespace) and the lecture page's source (`indexHtml`): each problem in words, [] when
 * all agree. The build fails on any (vite.config.js), and a unit test checks the same.
 * @param {string[]} files
 * @param {Record<string, string>} panelWords
 * @param {string} [indexHtml]
 * @param {readonly PanelEntry[]} [panels]
 */
export function manifestProblems(files, panelWords, indexHtml, panels = PANELS) {
  const problems = [];
  const ids = new Set();
  for (const entry of panels) {
    const { id } = entry;
    if (ids.has(id)) problems.push(`The id “${id}” is in the manifest twice.`);
    ids.add(id);
    if (!/^[a-z0-9]+(-[a-z0-9]+)*$/.test(id)) problems.push(`The id “${id}” is not lower-case words joined by hyphens.`);
    if (!files.includes(`${id}/index.js`)) problems.push(`The panel “${id}” has no module src/panels/${id}/index.js.`);
    if (!files.includes(`${id}/schema.js`)) {
      problems.push(`The panel “${id}” has no src/panels/${id}/schema.js: `
        + 'its parameters (export const schema) come with the page, apart from its module.');
    }
    const text = panelTextFrom(panelWords, id);
    for (const field of /** @type {const} */ (['title', 'lede', 'cite'])) {
      const words = text[field];
      if (typeof words !== 'string' || !words.trim()) {
        problems.push(`The panel “${id}” has no ${field} (“${id}.${field}” in locales/en.json, namespace "panels").`);
      }
    }
    if (typeof entry.webgl !== 'boolean') problems.push(`The panel “${id}” does not say whether it uses WebGL.`);
    if (entry.webglAtTimes !== undefined && (typeof entry.webglAtTimes !== 'boolean' || entry.webgl)) {
      problems.push(`The panel “${id}” has webglAtTimes ${String(entry.webglAtTimes)}: true or left out, and only with webgl false.`);
    }
    for (const [layout] of placeLayouts()) {
      const height = entry.place?.[layout];
      if (!(Number.isFinite(height) && height > 0)) {
        problems.push(`The panel “${id}” has no place.${layout}: `
          + 'the height in px the lecture page keeps for it before it mounts (docs/panels.md).');
      }
    }
  }
  for (const folder of new Set(files.map((file) => file.split('/')[0]))) {
    if (ids.has(folder)) continue;
    const own = files.filter((f) => f.startsWith(`${folder}/`)).map((f) => f.slice(folder.length + 1));
    problems.push(`src/panels/${folder}/ (${own.join(', ')}) is not in the manifest.`);
  }
  if (indexHtml !== undefined) {
    if (!indexHtml.includes(SECTIONS_MARKER)) problems.push('index.html has no place for the panel sections.');
    for (const match of indexHtml.matchAll(/data-panel="([^"]*)"/g)) {
      problems.push(`index.html has a hand-written section “${match[1]}”: sections come from the manifest.`);
    }
  }
  return problems;
}
