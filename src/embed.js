// embed.html?panel=ID&<params>: one panel alone, no page chrome, sized to its frame, driven by
// its URL and by the message API (src/ui/messageApi.js).
import './styles.css';
import { panelIds, panelLoaders } from './panels/registry.js';
import { createPanelHost } from './ui/createPanelHost.js';
import { connectMessages } from './ui/messageApi.js';
import { applyTheme, loadTheme } from './ui/theme.js';
import { showNotice } from './ui/notices.js';
import { contextStats } from './gl/createRenderer.js';

const root = document.getElementById('embed');
const search = new URLSearchParams(window.location.search);
const id = search.get('panel');
const hosts = {};
window.fresnelLab = {
  hosts, contexts: contextStats, panels: new Proxy({}, { get: (_t, key) => hosts[key]?.instance ?? null }), ready: null,
};
applyTheme({ ...loadTheme(), scheme: search.get('theme') === 'light' ? 'light' : loadTheme().scheme });

window.fresnelLab.ready = (async () => {
  if (!id || !Object.hasOwn(panelLoaders, id)) {
    showNotice(root, id ? `There is no panel called “${id}”.` : 'No panel was named in the link.', [
      `Use embed.html?panel=ID with one of: ${panelIds.join(', ')}.`,
    ], { kind: 'error' });
    return null;
  }
  const module = await panelLoaders[id]();
  document.title = `Fresnel Lab: ${module.title}`;
  const heading = document.createElement('h1');
  heading.className = 'embed-title';
  heading.textContent = module.title;
  root.append(heading);
  let messages = null;
  const host = createPanelHost(root, module, {
    applyMaterial: (material) => module.materialParam && host.set({ [module.materialParam]: material.n }),
    onFrame: (frame) => messages?.rendered(frame),
  });
  hosts[id] = host;
  messages = connectMessages(host);
  host.mount();
  messages.ready();
  return host;
})();
