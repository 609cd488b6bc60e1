// CodeMirror writes its styles (style-mod's StyleModule) into a <style> element of the document,
// which the pages' Content-Security-Policy refuses (no inline style). In a shadow root style-mod
// uses a constructed stylesheet instead, which a CSP does not govern; importing this module makes
// it do the same for the document itself. The sheet then follows the page's own stylesheets: the
// page's overrides of the editor (.sl-editor .cm-…) are the more specific, so they still win.
import { StyleModule } from 'style-mod';

const mount = StyleModule.mount;
// Where there is a document that takes constructed sheets (not in Node, where tests import panels).
if (typeof document !== 'undefined' && Array.isArray(document.adoptedStyleSheets)) {
  /** The document as style-mod sees a shadow root: no head, adopted stylesheets. */
  const adopting = {
    ownerDocument: document,
    get adoptedStyleSheets() { return document.adoptedStyleSheets; },
    set adoptedStyleSheets(sheets) { document.adoptedStyleSheets = sheets; },
  };
  StyleModule.mount = (root, modules, options) => mount(root === document ? adopting : root, modules, options);
}
