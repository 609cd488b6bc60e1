// Starting a panel's WebGL picture, with the fallback every panel shares: when the browser has no
// WebGL2 (or it will not start), the stage says so in words in place of the picture, and the rest
// of the panel (numbers, plots, formulas) goes on working.
import { WebGL2Unavailable } from '../../gl/webgl2Unavailable.js';
import { ShaderError } from '../../gl/shaderError.js';
import { el } from '../../ui/el.js';
import english from 'virtual:messages/en/panelsShared';
import { messages } from '../../i18n/messages.js';

const t = messages('panelsShared', english);

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

/** The driver's words on a shader it refused, short enough to read on the stage (the console has all of it). */
export function shaderFailureText(error, lines = 4) {
  const log = error.message.split('\n').map((line) => line.trim()).filter(Boolean);
  const shown = log.slice(0, lines).join(' ');
  return t('shaderRefused', { log: `${shown}${log.length > lines ? ' …' : ''}` });
}

/**
 * Returns start() (which creates the view), or null when WebGL2 is unavailable or this GPU
 * refuses the picture's shader (an unusual driver); then the stage shows why and what still
 * works. fallback: "The X needs WebGL2; the plot below still works." in the page's language (after a
 * refused shader only its part after the semicolon is said). Any other error is the panel's and propagates.
 */
export function startWebGL(stage, start, fallback) {
  try {
    return start();
  } catch (error) {
    if (error instanceof ShaderError) {
      console.error(error); // the whole log, for whoever reports it
      const rest = fallback.replace(/^[^;]*;\s*/, ''); // what still works, without "… needs WebGL2"
      showStageFallback(stage, `${shaderFailureText(error)} ${rest[0].toUpperCase()}${rest.slice(1)}`);
      return null;
    }
    if (!(error instanceof WebGL2Unavailable)) throw error;
    showStageFallback(stage, `${error.message} ${fallback}`);
    return null;
  }
}
