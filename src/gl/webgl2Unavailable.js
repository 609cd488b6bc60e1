// The error for a browser without WebGL2, or a context that would not start: thrown where a context
// is made (createContext.js, createRenderer.js), caught by panels that say so in words
// (showStageFallback, a read-back GPU's problem). A module of its own, without the DOM, so words
// that name the cause import it without the context budget's probe of the page.

/** WebGL2 is missing or would not start; panels catch it and say so in words (showStageFallback). */
export class WebGL2Unavailable extends Error {}
