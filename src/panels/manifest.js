// @ts-check
// The panel manifest: every panel of the lecture, in the lecture's order, with what the page needs
// to know before the panel's code loads. The lecture page's sections and the places they keep
// (vite.config.js writes them into index.html and src/panelPlaces.css), the embed page and the
// tests all come from this list or are checked against it. Plain data with no imports, so Node (the
// build, the unit tests) reads it too.
//
// A panel is the folder src/panels/<id>/ with its parameters in schema.js and its module in index.js
// (the same schema and mount; see src/host/panelContract.js). Adding a panel is adding its folder
// and one entry here (docs/panels.md).

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
 * @typedef {object} PanelEntry
 * @property {string} id            fixed: URLs and embeds depend on it
 * @property {string} title         plain text: the embed heading, window titles, the controls' title
 * @property {string} [titleHtml]   the lecture page's heading where it needs markup (subscripts)
 * @property {string} lede          HTML: the paragraph under the heading on the lecture page
 * @property {string} cite          HTML: where in the lecture (or beyond it) the concept comes from
 * @property {boolean} webgl        holds a WebGL context while mounted (counted against the budget)
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
    title: "Exact Fresnel vs Schlick's approximation",
    lede: `Each sphere is shaded with the lecture's coat model, k = (1 − F)·k<sub>d</sub> + F·k<sub>s</sub>: a diffuse colour
        and a mirrored sky weighed by one F at the view angle (a heuristic; Fresnel in lighting below shows how a layered
        coat differs). The first sphere takes the exact Fresnel reflectance, the second Schlick's cheap polynomial, `
      + `the third shows how far apart they are.
        Both agree head-on and part near the rim, where the view grazes the surface.
        Swap the indices to look out of the glass: past the critical angle all light is reflected, and Schlick misses it.`,
    cite: 'Lecture: “Reflection Math”, “Fresnel Reflection in Lighting”.',
    webgl: true,
    material: 'nT',
    place: { narrow: 1290, wide: 760, widest: 800 },
  },
  {
    id: 'normal-mips',
    title: 'Mipmapping normal maps',
    lede: `A mipmap level stores the average of the texels below it. For colours stored in linear space that is right;
        for normals it is not: averaging unit normals that point different ways gives a shorter vector, and renormalizing
        it throws away the spread that made the surface look rough. Far away, a bumpy surface turns too shiny. Compare how
        each technique keeps that spread against the ground truth, with numbers.`,
    cite: 'Lecture agenda: “Mipmapping normal maps”; Toksvig 2005, Olano &amp; Baker 2010.',
    webgl: true,
    material: null,
    place: { narrow: 2560, wide: 1780, widest: 1920 },
  },
  {
    id: 'asphalt',
    title: 'Does asphalt have a specular highlight?',
    lede: `Look straight down at a road and it is dull; look along it towards a low sun and it shines. Nothing about
        the asphalt changed, only the angle, and two things grow with it. From the road straight below you to the road at
        the horizon, with the sun 10° up, the rough microfacets' lobe, which leans forward towards grazing views, makes the
        specular light about 19× brighter (with Fresnel off, that is all that grows), and F at the angle between the sun
        and the half-vector rises about 12×. Even so, with the sun 10° up the road reflects only about 7 % of the sunlight
        specularly, less than its diffuse albedo of 9 %: the sheen is bright because that light is concentrated, not
        because there is much of it. Switch Fresnel off to see what a model without it misses.`,
    cite: 'Lecture: “Specular”.',
    webgl: true,
    material: 'nT',
    place: { narrow: 970, wide: 610, widest: 710 },
  },
  {
    id: 'changing-specular',
    title: 'Changing specular',
    lede: `Phong's highlight, (v·r)<sup>s</sup>, only asks how close the view is to the mirror direction. It never asks how
        the reflected ray meets the surface, so its highlight is as bright overhead as at grazing. Multiply by F and the
        highlight grows as the light and view drop towards the surface, as real ones do.`,
    cite: 'Lecture: “Changing Specular”.',
    webgl: true,
    material: 'nT',
    place: { narrow: 1190, wide: 850, widest: 860 },
  },
  {
    id: 'reflect-refract',
    title: 'Reflection vs refraction',
    lede: `At a water surface, part of the light is reflected (you see the sky) and the rest is refracted (you see the
        floor below). Which part wins depends on the angle: looking down you see through, looking across you see the sky.
        F splits the two, R + T = 1. Light from the floor also spreads into a wider cone as it leaves the water, which
        divides its radiance by n<sub>t</sub>².`,
    cite: 'Lecture: “Reflection vs. Refraction”.',
    webgl: true,
    material: 'nT',
    place: { narrow: 1050, wide: 630, widest: 740 },
  },
  {
    id: 'refraction-waves',
    title: 'Wave theory: why light bends',
    lede: `In a material of index n the crests of a light wave travel at c/n (the phase speed; a pulse travels a little
        slower, at c/n<sub>g</sub>). When a wavefront crosses into a slower medium, the part that enters first slows first,
        so the front turns: Snell's law, n<sub>i</sub> sin θ<sub>i</sub> = n<sub>t</sub> sin θ<sub>t</sub>.
        Going into a faster medium past the critical angle, no propagating transmitted wave can match the front (only an
        evanescent field that fades with depth and carries no light away), and all of the light is reflected.`,
    cite: 'Lecture: “Wave Theory – Refraction”.',
    webgl: true,
    material: 'nT',
    animates: 'play',
    place: { narrow: 1160, wide: 760, widest: 880 },
  },
  {
    id: 'angle-ratio',
    title: 'The ratio of reflection to refraction depends on the angle',
    lede: `The wider the angle between the light and the normal, the more of it is reflected and the less goes in.
        The widths of the rays below carry R and T.`,
    cite: 'Lecture: “Reflection vs. Refraction”.',
    webgl: false,
    material: 'nT',
    place: { narrow: 930, wide: 650, widest: 740 },
  },
  {
    id: 'refractive-index',
    title: 'Fresnel reflection: the refractive index',
    lede: `The refractive index n is the ratio of the speed of light in a vacuum to its phase speed in the material;
        glass is about 1.5. How much a dielectric reflects head-on (R0) and the angle past which light cannot get out
        (the critical angle) depend on the ratio of the indices on the two sides, n<sub>t</sub>/n<sub>i</sub>, not on n
        alone: glass of 1.5 reflects 0.04 head-on in air but 0.0035 under water. The table gives both with air on the
        other side. Pick a row to use that material in every panel.`,
    cite: 'Lecture: “Fresnel Reflection”.',
    webgl: false,
    material: null,
    materialSelect: 'selected',
    place: { narrow: 1430, wide: 1260, widest: 810 },
  },
  {
    id: 'polarization',
    title: 'Why the exact formula is an average: polarization',
    lede: `Light polarized across the plane of incidence (s) and within it (p) reflect differently. The lecture's formula is
        their average, the right answer for unpolarized light. At Brewster's angle p-light is not reflected at all.`,
    cite: 'Beyond the slides; Hecht, <i>Optics</i>, §4.6.',
    webgl: false,
    material: 'nT',
    place: { narrow: 950, wide: 650, widest: 590 },
  },
  {
    id: 'exact-fresnel',
    title: 'Reflection math: the exact formula',
    lede: `The fraction of light reflected, evaluated term by term as you move the sliders. Past the critical angle g² turns
        negative: g would be imaginary, and the reflectance is exactly 1.`,
    cite: 'Lecture: “Reflection Math”.',
    webgl: false,
    material: 'nT',
    place: { narrow: 1600, wide: 1350, widest: 780 },
  },
  {
    id: 'schlick',
    title: "Schlick's approximation",
    lede: `R(θ) ≈ R0 + (1 − R0)(1 − cos θ)<sup>5</sup>: one constant computed once, a few multiplications per pixel.
        How close is it, where is it worst, and what goes wrong from inside the glass?`,
    cite: 'Lecture: “Reflection Math”.',
    webgl: false,
    material: 'nT',
    place: { narrow: 1000, wide: 760, widest: 700 },
  },
  {
    id: 'r0-derivation',
    title: 'R(0°): from the exact formula to ((n_t − n_i)/(n_t + n_i))²',
    titleHtml: 'R(0°): from the exact formula to ((n<sub>t</sub> − n<sub>i</sub>)/(n<sub>t</sub> + n<sub>i</sub>))²',
    lede: `Set θ = 0 and the exact formula collapses to one square. Every line below is evaluated with the current indices:
        they are all the same number.`,
    cite: 'Lecture: “Reflection Math”, R(0°).',
    webgl: false,
    material: 'nT',
    place: { narrow: 1430, wide: 1290, widest: 1210 },
  },
  {
    id: 'fresnel-lighting',
    title: 'Fresnel reflection in lighting',
    lede: `The lecture's model of a diffuse surface under a shiny coat weighs the two by F at the view angle,
        k = mix(k<sub>d</sub>, k<sub>s</sub>, F). Compare with a constant k<sub>s</sub>, copy the GLSL, and switch to the
        layered coat to see what the heuristic leaves out.`,
    cite: 'Lecture: “Fresnel Reflection in Lighting”.',
    webgl: true,
    material: 'nT',
    place: { narrow: 1390, wide: 880, widest: 1000 },
  },
  {
    id: 'metals',
    title: 'Dielectrics vs metals',
    lede: `Plastic, glass and paint reflect a few per cent head-on and more only towards grazing. A metal's index is
        complex, n + ik, and differs per wavelength: head-on it reflects far more (from 0.41 to 0.99 of the light per channel for the
        metals here), with a colour for gold and copper, nearly neutral for silver, aluminium and iron. It still has a Fresnel
        factor: towards grazing R first dips below F0 in most channels (aluminium's red by 0.08, near 82°; gold's blue not
        at all), then rises to 1 in every channel, and a coloured metal's tint fades to white.`,
    cite: 'Lecture: “Fresnel Reflection and Materials”.',
    webgl: true,
    material: 'nT',
    place: { narrow: 1440, wide: 1180, widest: 1200 },
  },
  {
    id: 'speed-accuracy',
    title: 'Both speed and accuracy count',
    lede: `Every Fresnel method, measured on the device in front of you: what it costs per evaluation and how wrong it is.
        Pick a scene to see which method it needs: the cheapest one whose error is no larger than the rounding an 8-bit
        display already makes (half a code), or within a budget you choose.`,
    cite: 'Beyond the slides: “model no more than a scene needs”.',
    webgl: false, // the chart is 2D; contexts live only while a benchmark or a read-back runs
    material: null,
    place: { narrow: 1750, wide: 1570, widest: 1080 },
  },
  {
    id: 'stability',
    title: 'Where methods fail',
    lede: `A map over every angle and index ratio: where a method returns NaN, leaves [0, 1], or strays past a tolerance,
        computed on this GPU and in JavaScript side by side. The order of operations and the precision decide.`,
    cite: 'Beyond the slides.',
    webgl: true,
    material: null,
    place: { narrow: 1040, wide: 810, widest: 820 },
  },
  {
    id: 'shader-lab',
    title: 'Write the Fresnel function',
    lede: `Write it in GLSL, as the lecture's code does: this GPU compiles it and evaluates it over total internal
        reflection, the critical angle to a hundred-thousandth of a degree, grazing, cos θ a hair outside [0, 1] and
        matched indices, in highp and in mediump, and every value is checked against the float64 optics core.
        Each exercise states its criteria first.`,
    cite: 'Lecture: “Fresnel Reflection in Lighting” (the shader code); beyond the slides.',
    webgl: true,
    material: null,
    place: { narrow: 1640, wide: 1400, widest: 1430 },
  },
]);

/** Panel ids in lecture order. */
export const PANEL_IDS = Object.freeze(PANELS.map((p) => p.id));

/** The manifest entry of a panel id, or undefined. */
export function panelEntry(id) {
  return PANELS.find((p) => p.id === id);
}

/** URL key prefix of a panel on the lecture page: the hero owns the short keys. */
export function lecturePrefix(id) {
  return panelEntry(id)?.hero ? '' : `${id}.`;
}

/** The lecture page's <section> for a panel: heading, lede with its citation, and the mount point. */
export function sectionHtml(entry) {
  const heading = entry.titleHtml ?? entry.title.replace(/&/g, '&amp;').replace(/</g, '&lt;');
  return `<section data-panel="${entry.id}" id="${entry.id}" class="panel${entry.hero ? ' hero' : ''}" tabindex="-1" `
    + `aria-labelledby="${entry.id}-title">
      <h2 id="${entry.id}-title">${heading}</h2>
      <p class="lede">
        ${entry.lede.trim()}
        <span class="cite">(${entry.cite})</span>
      </p>
      <div class="panel-mount"></div>
    </section>`;
}

/** Where the lecture page's sections go in index.html. */
export const SECTIONS_MARKER = '<!-- panel sections: written at build time from src/panels/manifest.js -->';

/** The media query of each layout of a PanelPlace ('' for every window), narrowest first. */
export const PLACE_LAYOUTS = Object.freeze({ narrow: '', wide: '(min-width: 1001px)', widest: '(min-width: 1450px)' });

/** Where the rules that keep each panel's place go in src/panelPlaces.css. */
export const PLACES_MARKER = '/* panel places: written at build time from src/panels/manifest.js */';

/**
 * The CSS that keeps each panel's place on the lecture page before it mounts, from the entries'
 * `place`: the page reserves it before any script runs, under the page's style-src 'self'.
 * @param {readonly PanelEntry[]} [panels]
 */
export function placesCss(panels = PANELS) {
  return Object.entries(PLACE_LAYOUTS).map(([layout, media]) => {
    const rules = panels.map((p) => `#${p.id} > .panel-mount { min-height: ${p.place[layout]}px; }`);
    return media ? `@media ${media} {\n  ${rules.join('\n  ')}\n}` : rules.join('\n');
  }).join('\n');
}

/**
 * What is wrong between the manifest, the panels' files (`files`: each index.js and schema.js
 * under src/panels, as `<folder>/<file>`) and the lecture page's source (`indexHtml`): each problem
 * in words, [] when all agree. The build fails on any (vite.config.js), and a unit test checks the same.
 * @param {string[]} files
 * @param {string} [indexHtml]
 * @param {readonly PanelEntry[]} [panels]
 */
export function manifestProblems(files, indexHtml, panels = PANELS) {
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
    for (const field of ['title', 'lede', 'cite']) {
      if (typeof entry[field] !== 'string' || !entry[field].trim()) problems.push(`The panel “${id}” has no ${field}.`);
    }
    if (typeof entry.webgl !== 'boolean') problems.push(`The panel “${id}” does not say whether it uses WebGL.`);
    for (const layout of Object.keys(PLACE_LAYOUTS)) {
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
