// The lecture page: every panel section in lecture order, mounted as it approaches the screen,
// plus the page controls and lecture-mode keys.
import './styles.css';
import { panelLoaders } from './panels/registry.js';
import { createPanelHost } from './ui/createPanelHost.js';
import { lecturePrefix } from './ui/shareLinks.js';
import { managePanels } from './ui/managePanels.js';
import { setupLectureMode } from './ui/lectureMode.js';
import { setupPageControls } from './ui/pageControls.js';
import { showNotice } from './ui/notices.js';
import { contextStats, MAX_LIVE_CONTEXTS } from './gl/createRenderer.js';
import { describeProblem, readParams } from './ui/params.js';

const hosts = {};
window.fresnelLab = {
  hosts,
  contexts: contextStats,
  /** Each mounted panel's view (null while it is away), for scripts and tests. */
  panels: new Proxy({}, { get: (_t, id) => hosts[id]?.instance ?? null }),
  ready: null,
};

/** Page-wide material: every panel that has an index parameter takes it (a table marks its row). */
function applyMaterial(material) {
  for (const host of Object.values(hosts)) {
    const { materialParam, materialSelectParam } = host.module;
    if (materialParam) host.set({ [materialParam]: material.n });
    else if (materialSelectParam && material.id) host.set({ [materialSelectParam]: material.id });
  }
}

const controls = setupPageControls(document.querySelector('.page-controls'), { onMaterial: applyMaterial });
window.fresnelLab.applyMaterial = applyMaterial;

// ?maxContexts=N holds fewer WebGL panels at once, for a weak laptop (at most 8, the default).
const pageSchema = {
  maxContexts: { type: 'number', default: MAX_LIVE_CONTEXTS, min: 1, max: MAX_LIVE_CONTEXTS, step: 1, label: 'Live WebGL panels' },
};
const page = readParams(pageSchema, new URLSearchParams(window.location.search));
showNotice(document.querySelector('main'), 'A page setting in the link was not usable:', page.problems.map(describeProblem));
const maxLive = Math.round(page.values.maxContexts);

// A section whose panel is not in this build is left out rather than shown empty.
for (const section of document.querySelectorAll('section[data-panel]')) {
  if (!(section.dataset.panel in panelLoaders)) section.remove();
}
const sections = [...document.querySelectorAll('section[data-panel]')];
window.fresnelLab.ready = (async () => {
  const entries = await Promise.all(sections.map(async (section) => {
    const id = section.dataset.panel;
    try {
      const module = await panelLoaders[id]();
      hosts[id] = createPanelHost(section.querySelector('.panel-mount'), module, {
        prefix: lecturePrefix(id), noticeHost: section, applyMaterial,
      });
      return { section, host: hosts[id] };
    } catch (error) {
      showNotice(section, `The ${id} panel could not load.`, [error.message], { kind: 'error' });
      return null;
    }
  }));
  const lecture = setupLectureMode(sections, { onHideControls: controls.toggleControls });
  const manager = managePanels(entries.filter(Boolean), { maxLive });
  lecture.holdHashTarget(manager.first);
  await manager.first; // `ready` means the panels on screen are mounted
})();
