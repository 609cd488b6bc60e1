// Starting a panel's WebGL picture, with the fallback every panel shares: when the browser has no
// WebGL2 (or it will not start), the stage says so in words in place of the picture, and the rest
// of the panel (numbers, plots, formulas) goes on working.
import { WebGL2Unavailable } from '../../gl/contextBudget.js';
import { el } from '../../ui/el.js';

/** Replaces what the stage shows with a message (its children stay in the DOM, out of sight). */
export function showStageFallback(stage, text) {
  for (const child of stage.children) {
    child.hidden = true;
    child.style.display = 'none'; // a stage's own CSS (display: block) would beat [hidden]
  }
  const message = el('p', 'stage-message', text);
  message.setAttribute('role', 'status');
  stage.append(message);
  stage.classList.add('no-gl');
  return message;
}

/**
 * Returns start() (which creates the view), or null when WebGL2 is unavailable; then the stage
 * shows why and `fallback`, a sentence on what still works ("the plot below still works").
 * Any other error is the panel's and propagates.
 */
export function startWebGL(stage, start, fallback) {
  try {
    return start();
  } catch (error) {
    if (!(error instanceof WebGL2Unavailable)) throw error;
    showStageFallback(stage, `${error.message} ${fallback}`);
    return null;
  }
}
