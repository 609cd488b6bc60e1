// The panel catalogue in lecture order. Ids are fixed: URLs and embeds depend on them.
// A panel is the module src/panels/<id>.js; each is loaded on demand, so an embed downloads only
// the panel it shows.
export const PANEL_CATALOGUE = [
  'spheres', 'normal-mips', 'asphalt', 'changing-specular', 'reflect-refract', 'refraction-waves',
  'angle-ratio', 'refractive-index', 'polarization', 'exact-fresnel', 'schlick', 'r0-derivation',
  'fresnel-lighting', 'metals', 'speed-accuracy', 'stability',
];

const modules = import.meta.glob('./*.js');

export const panelLoaders = Object.fromEntries(PANEL_CATALOGUE
  .filter((id) => modules[`./${id}.js`])
  .map((id) => [id, modules[`./${id}.js`]]));

export const panelIds = Object.keys(panelLoaders);
