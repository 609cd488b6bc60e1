// The code editor: CodeMirror 6 with GLSL highlighting (the C-like "shader" mode of
// @codemirror/legacy-modes), line numbers, undo, bracket matching, and compile errors marked at
// their lines (@codemirror/lint). Tab is left to moving focus, as the WAI-ARIA guidance on code
// editors and CodeMirror's own default have it (Escape, then Tab, leaves it too); Ctrl+Enter
// (⌘Enter) grades. Its colours and size come from the page's theme, and long lines wrap, so it
// reads on a projector.
import '../../ui/adoptStyleModules.js'; // before any editor: its styles as a constructed sheet (CSP)
import { EditorState, Compartment, Transaction } from '@codemirror/state';
import { EditorView, keymap, lineNumbers, highlightActiveLine, drawSelection } from '@codemirror/view';
import { defaultKeymap, history, historyKeymap } from '@codemirror/commands';
import { HighlightStyle, StreamLanguage, bracketMatching, indentOnInput, syntaxHighlighting } from '@codemirror/language';
import { tags } from '@lezer/highlight';
import { shader } from '@codemirror/legacy-modes/mode/clike';
import { lintGutter, setDiagnostics } from '@codemirror/lint';

// The code's colours are the page theme's (--code-* in styles.css), each at least 4.5:1 against
// the editor's background and its active line in both themes (WCAG 2.2, 1.4.3).
const glslColours = HighlightStyle.define([
  { tag: [tags.keyword, tags.modifier], color: 'var(--code-keyword)' },
  { tag: [tags.typeName, tags.className, tags.namespace], color: 'var(--code-type)' },
  { tag: [tags.number, tags.bool, tags.atom, tags.literal], color: 'var(--code-number)' },
  { tag: tags.string, color: 'var(--code-string)' },
  { tag: [tags.comment, tags.lineComment, tags.blockComment], color: 'var(--code-comment)', fontStyle: 'italic' },
  { tag: [tags.standard(tags.variableName), tags.macroName, tags.meta], color: 'var(--code-builtin)' },
  { tag: tags.invalid, color: 'var(--code-invalid)' },
]);

// CodeMirror leaves typing to the browser and reads the change back from the DOM. Typing over a
// selection, Chrome's own editing deletes it first and writes style attributes into the lines it
// merges (to keep the look of the text it removed), which the page's Content-Security-Policy
// refuses and reports. So the editor replaces a selection itself (not while an input method
// composes), and the browser's editing never runs there.
const typeOverSelection = EditorView.domEventHandlers({
  beforeinput(event, view) {
    if (event.inputType !== 'insertText' || event.isComposing || typeof event.data !== 'string') return false;
    if (view.state.selection.ranges.every((range) => range.empty)) return false;
    event.preventDefault();
    if (!view.state.readOnly) view.dispatch(view.state.replaceSelection(event.data), { userEvent: 'input.type', scrollIntoView: true });
    return true;
  },
});

/**
 * parent: where the editor goes; doc: its text; label: its accessible name; onChange(text) after
 * each edit; onRun() on Ctrl+Enter. Returns { view, text(), setText(text), setErrors([{ line,
 * message }]), setReadOnly(on), focus(), destroy() }.
 */
export function createCodeEditor(parent, { doc, label, onChange, onRun }) {
  const readOnly = new Compartment();
  const view = new EditorView({
    parent,
    state: EditorState.create({
      doc,
      extensions: [
        lineNumbers(),
        history(),
        drawSelection(),
        highlightActiveLine(),
        bracketMatching(),
        indentOnInput(),
        StreamLanguage.define(shader),
        syntaxHighlighting(glslColours),
        lintGutter(),
        EditorView.lineWrapping, // long lines wrap: nothing is cut off on a projector
        typeOverSelection,
        keymap.of([{ key: 'Mod-Enter', run: () => { onRun(); return true; } }, ...defaultKeymap, ...historyKeymap]),
        EditorView.contentAttributes.of({ 'aria-label': label }),
        // Only what the student typed: the page's own replacements (remote) are not a change of theirs.
        EditorView.updateListener.of((update) => {
          const typed = update.docChanged && !update.transactions.some((t) => t.annotation(Transaction.remote));
          if (typed) onChange(update.state.doc.toString());
        }),
        readOnly.of(EditorState.readOnly.of(false)),
      ],
    }),
  });
  return {
    view,
    text: () => view.state.doc.toString(),
    /**
     * Replaces the text (a reference answer, a value from the link or a message). history: false
     * for a new exercise, so undo cannot bring the last exercise's code into this one.
     */
    setText(text, { history = true } = {}) {
      if (text === view.state.doc.toString()) return;
      view.dispatch({
        changes: { from: 0, to: view.state.doc.length, insert: text },
        annotations: [Transaction.addToHistory.of(history), Transaction.remote.of(true)],
      });
    },
    /** Marks each error at its line (1-based, of this text); an error without a line marks line 1. */
    setErrors(errors) {
      const { doc: current } = view.state;
      const diagnostics = errors.map(({ line, message }) => {
        const at = current.line(Math.min(Math.max(1, line ?? 1), current.lines));
        return { from: at.from, to: at.to, severity: 'error', message };
      });
      view.dispatch(setDiagnostics(view.state, diagnostics));
    },
    setReadOnly(on) {
      view.dispatch({ effects: readOnly.reconfigure(EditorState.readOnly.of(on)) });
    },
    focus: () => view.focus(),
    destroy: () => view.destroy(),
  };
}
