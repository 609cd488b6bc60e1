// embed.html?panel=ID&<params>: one panel alone, no page chrome, sized to its frame.
import './styles.css';
import { panelIds, panelLoaders } from './panels/registry.js';
import { mountPanel } from './ui/mountPanel.js';
import { showNotice } from './ui/notices.js';

const root = document.getElementById('embed');
const id = new URLSearchParams(window.location.search).get('panel');
window.fresnelLab = { panels: {}, ready: null };

if (id && Object.hasOwn(panelLoaders, id)) {
  document.title = `Fresnel Lab: ${id}`;
  window.fresnelLab.ready = mountPanel(root, id);
} else {
  showNotice(root, id ? `There is no panel called “${id}”.` : 'No panel was named in the link.', [
    `Use embed.html?panel=ID with one of: ${panelIds.join(', ')}.`,
  ], { kind: 'error' });
  window.fresnelLab.ready = Promise.resolve(null);
}
