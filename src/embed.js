// embed.html?panel=ID&<params>: one panel alone, no page chrome, sized to its frame, driven by
// its URL and by the message API (src/host/messageApi.js).
import './styles.css';
import { PANEL_IDS, panelEntry } from './panels/manifest.js';
import { loadPanel } from './panels/loadPanel.js';
import { createPanelHost } from './host/createPanelHost.js';
import { connectMessages } from './host/messageApi.js';
import { applyTheme, loadTheme } from './ui/theme.js';
import { setSubscripted } from './ui/subscripts.js';
import { showNotice } from './host/showNotice.js';
import { contextStats } from './gl/contextBudget.js';

const root = document.getElementById('embed');
const search = new URLSearchParams(window.location.search);
const id = search.get('panel');
const hosts = {};
window.fresnelLab = {
  hosts, contexts: contextStats, panels: new Proxy({}, { get: (_t, key) => hosts[key]?.instance ?? null }), ready: null,
};
applyTheme({ ...loadTheme(), scheme: search.get('theme') === 'light' ? 'light' : loadTheme().scheme });

window.fresnelLab.ready = (async () => {
  const entry = id ? panelEntry(id) : undefined;
  if (!entry) {
    showNotice(root, id ? `There is no panel called “${id}”.` : 'No panel was named in the link.', [
      `Use embed.html?panel=ID with one of: ${PANEL_IDS.join(', ')}.`,
    ], { kind: 'error' });
    return null;
  }
  document.title = `Fresnel Lab: ${entry.title}`;
  const heading = document.createElement('h1');
  heading.className = 'embed-title';
  setSubscripted(heading, entry.title); // n_t with a real subscript, as the lecture page's heading
  root.append(heading);
  let panel;
  try {
    panel = await loadPanel(id);
  } catch (error) {
    showNotice(root, `The ${entry.title} panel could not load.`, [error.message], { kind: 'error' });
    return null;
  }
  let messages = null;
  const host = createPanelHost(root, panel, {
    applyMaterial: (material) => panel.material && host.set({ [panel.material]: material.n }, { source: 'page' }),
    onFrame: (frame) => messages?.rendered(frame),
  });
  hosts[id] = host;
  messages = connectMessages(host);
  host.mount();
  messages.ready();
  return host;
})();
