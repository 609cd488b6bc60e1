// The panel ids that links, embeds and homework sheets already use, as the lecture had them when
// they were written. Renaming or removing one breaks every link made with it, so the tests hold the
// manifest to them; a panel added since is not listed (it needs only its folder and its entry).
export const FIXED_PANEL_IDS = Object.freeze([
  'spheres', 'normal-mips', 'asphalt', 'changing-specular', 'reflect-refract', 'refraction-waves',
  'angle-ratio', 'refractive-index', 'polarization', 'exact-fresnel', 'schlick', 'r0-derivation',
  'fresnel-lighting', 'metals', 'speed-accuracy', 'stability', 'shader-lab',
]);
