// Mounts one panel: its values from the URL (bad ones reported on screen), its URL kept in step,
// and a handle on window.fresnelLab for scripts, tests and (later) the deck message API.
import { panelLoaders } from '../panels/registry.js';
import { describeProblem } from './params.js';
import { readUrlState, urlWriter } from './urlState.js';
import { showNotice } from './notices.js';

export async function mountPanel(host, id, { prefix = '', noticeHost = host } = {}) {
  const module = await panelLoaders[id]();
  const { values, problems } = readUrlState(module.schema, prefix);
  showNotice(noticeHost, 'Some values in the link were not usable:', problems.map(describeProblem));
  const write = urlWriter(module.schema, prefix);
  let instance;
  try {
    instance = module.mount(host, { values, onChange: write });
  } catch (error) {
    showNotice(noticeHost, `The ${id} panel could not start.`, [error.message], { kind: 'error' });
    throw error;
  }
  window.fresnelLab ??= { panels: {} };
  window.fresnelLab.panels[id] = instance;
  return instance;
}
