// Panel ids (fixed: URLs and embeds depend on them) and how to load each panel's module.
// Loaded on demand so an embed downloads only the panel it shows.
export const panelLoaders = {
  spheres: () => import('./spheres.js'),
};

export const panelIds = Object.keys(panelLoaders);
