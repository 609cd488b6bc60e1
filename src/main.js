// The lecture page: mount every panel section in order.
import './styles.css';
import { mountPanel } from './ui/mountPanel.js';

window.fresnelLab = { panels: {}, ready: null };
const sections = [...document.querySelectorAll('section[data-panel]')];
window.fresnelLab.ready = Promise.allSettled(sections.map((section) => {
  const host = section.querySelector('.panel-mount');
  const id = section.dataset.panel;
  // The hero owns the short, unprefixed URL keys (?nI=1&nT=1.5); other panels use "id.key".
  return mountPanel(host, id, { prefix: id === 'spheres' ? '' : `${id}.`, noticeHost: section });
}));
