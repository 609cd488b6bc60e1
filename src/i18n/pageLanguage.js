// What every page does first: choose its language (language.js), and where that is not English put
// the page's own words in it (translatePage.js). Resolves to { id, problem }: problem is why the
// chosen language could not load (the page then speaks English), for the page to say.
import { SOURCE_LANGUAGE } from './languages.js';
import { startLanguage } from './language.js';
import { translatePage } from './translatePage.js';

/** @param {{ carried?: unknown, stored?: boolean }} [options] */
export async function startPageLanguage(options = {}) {
  const started = await startLanguage(options);
  if (started.id !== SOURCE_LANGUAGE) translatePage(document);
  return started;
}
