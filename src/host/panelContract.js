// @ts-check
// The contract between the host and a panel, written down once. A panel is a folder
// src/panels/<id>/ whose schema.js exports `schema` and whose index.js exports the same `schema` and
// `mount`; everything else the page needs (id, title, traits, place) is its entry in
// src/panels/manifest.js. tests/e2e/contract.spec.js checks every panel of the manifest against
// this contract.

/**
 * One parameter. The schema is the single source of truth for the panel's controls, its URL keys
 * and its messages; a value that breaks it is reported and replaced by the default. Each type has
 * its own fields:
 * @typedef {NumberSpec | EnumSpec | ColorSpec | BooleanSpec | TextSpec} ParamSpec
 */

/**
 * What every type may have.
 * @typedef {object} SpecCommon
 * @property {string[]} [aliases]  older keys that still read, so links made before a rename work
 */

/**
 * @typedef {SpecCommon & {
 *   type: 'number', default: number, min: number, max: number,
 *   step?: number,
 *   integer?: boolean,
 * }} NumberSpec  step also sets how many decimals the URL keeps; integer: whole numbers only (an index or a count)
 */

/**
 * @typedef {SpecCommon & { type: 'enum', default: string, options: string[] | Record<string, string> }} EnumSpec
 *   options: the values (their names, and the control's, are the catalogue's: controlText.js); an object's keys are
 *   the values too
 */

/** @typedef {SpecCommon & { type: 'color', default: string }} ColorSpec  a colour as #rrggbb */

/** @typedef {SpecCommon & { type: 'boolean', default: boolean }} BooleanSpec */

/**
 * @typedef {SpecCommon & {
 *   type: 'text', default: string, maxLength: number,
 *   encode?: (text: string) => string,
 *   decode?: (raw: string) => string | null,
 *   defaultText?: string,
 * }} TextSpec  maxLength: the longest accepted; encode: the compact form the link writes; decode: the link's form (or
 *   plain text) back, null if unreadable; defaultText: the default in words, for a notice (the text itself may be long
 *   or empty): the key of those words in the catalogue, host.defaultText.<key>
 */

/** @typedef {Record<string, ParamSpec>} Schema */

/** One value, as the schema's type makes it: a number, an enum's option or a colour or text, a boolean. */
/** @typedef {number | string | boolean} Value */

/** A panel's values, by schema key. @typedef {Record<string, Value>} Values */

/**
 * The value a spec gives: a number, a boolean, or text (an enum's option, a colour, a text).
 * Distributes over a union, so ValueOf<ParamSpec> is Value.
 * @template {ParamSpec} P
 * @typedef {P extends { type: 'number' } ? number : P extends { type: 'boolean' } ? boolean : string} ValueOf
 */

/**
 * A panel's values typed from its schema: { nI: number, exercise: string, … }. The schema keeps
 * each `type` as a literal when it is declared with `@satisfies {Schema}` (schema.js); of the plain
 * `Schema` it is Readonly<Values>.
 * @template {Schema} S
 * @typedef {{ readonly [K in keyof S]: ValueOf<S[K]> }} ValuesOf
 */

/**
 * What a set did. applied: the values taken, by key; rejected: the names and values refused, and
 * why; changed: the keys whose value is now different; refused: the change touched a control a deck
 * has locked, and nothing of it was applied.
 * @typedef {{ applied: Values, rejected: import('./params.js').Problem[], changed: string[], refused: boolean }} SetResult
 */

/**
 * Where a change came from: a control or the panel's own picture ('user'), a message ('api'), or
 * the page-wide material ('page'). (Values read from the link at start are not a change.)
 * @typedef {'user'|'api'|'page'} ChangeSource
 */

/**
 * What mount() gets. S: the panel's schema (`PanelContext<typeof schema>`), which types `values`.
 * @template {Schema} [S=Schema]
 * @typedef {object} PanelContext
 * @property {ValuesOf<S>} values  the current values, read-only (writing one throws): the host owns them
 * @property {(update: Record<string, unknown>, options?: { source?: ChangeSource }) => SetResult} set
 *   change values: validated, then controls, URL, picture and messages follow (update(keys) runs).
 *   Called inside update, the host runs update again with those keys once this one returns;
 *   called during mount (before mount returns), it sets the values, the controls and the link, and
 *   tells no listener: where a panel starts is no change (a deck reads those values from ready).
 * @property {() => void} invalidate  something other than the values changed (a result arrived): update([]) and describe() again
 * @property {import('lil-gui').default} gui  this mount's lil-gui root
 * @property {(folder: import('lil-gui').default | null, keys: string[]) => Record<string, import('lil-gui').Controller>} bind
 *   controllers for these schema keys in a folder (or the root)
 * @property {<C extends import('./createControlState.js').Control>(controller: C, keys: string[]) => C} tie  a control of the
 *   panel's own that changes `keys` (a preset, a button): a deck's lock or hide of those keys applies to it too; returns
 *   the controller
 * @property {() => void} frameDrawn  call after each WebGL frame (frame counters, `rendered` messages)
 * @property {(material: { id?: string, name?: string, n: number }) => void} applyMaterial  to every panel of the page
 * @property {boolean} reducedMotion  the reader (or the embed's link or deck) asked for reduced motion
 */

/**
 * What mount() returns: these, and members of its own that tests and the benchmark read (a scene,
 * a plot, its runs: `unknown` here, typed where the panel makes them).
 * @typedef {object} PanelCore
 * @property {(keys?: string[]) => void} update  values changed (keys: which; [] for a re-describe)
 * @property {() => string} describe  the key numbers in words: shown under the panel, and every canvas's description
 * @property {(() => CsvTable) | null} [csv]  the plotted numbers
 * @property {(() => string | null) | null} [png]  a PNG data URL of the picture
 * @property {AudioTrace} [trace]  the audio trace of its R(θ) plot, where it has one
 * @property {() => void} dispose  free everything: contexts, observers, listeners, timers
 */

/** @typedef {{ filename?: string, columns: Record<string, ArrayLike<number | string>> }} CsvTable */

/**
 * The audio trace under an R(θ) plot (src/ui/createAudioTrace.js), as tests and decks drive it.
 * @typedef {object} AudioTrace
 * @property {HTMLElement} element
 * @property {number} deg  where its cursor is (degrees)
 * @property {string | null} readout  the words read out there
 * @property {(to: number) => void} moveTo  move the cursor as the keys do
 * @property {() => void} refresh  the values changed: the words and the cursor follow
 * @property {() => void} dispose
 */

/** @typedef {PanelCore & { [member: string]: unknown }} PanelInstance */

// Besides its view (index.js), its DOM builders and its scene, a panel's folder may hold one module
// of each kind below, always under the kind's name, so a reader knows what a file may do before
// opening it. Helpers a kind's module imports from the folder are held to the same rules.
// tests/unit/layers.test.js checks them; docs/panels.md lists them.

/**
 * `physics.js`: the math only this panel uses, as pure float64 functions of numbers and plain
 * values, and its constants. No state, no words, no DOM: it imports src/optics, src/methods,
 * src/normals and its folder's own physics, nothing else. The panel's numbers, its shader's
 * uniforms, its homework questions and its Node tests all come from it.
 * @typedef {{ [name: string]: ((...values: any[]) => any) | number | string | object }} PanelPhysics
 */

/**
 * `words.js`: what the panel says, as pure functions of its values and of a snapshot of what its
 * runs hold: sentences from the catalogue (src/i18n/messages.js; numbers written by src/ui/format.js),
 * labels, the description, and the columns of its CSV. No state of its own and no DOM, so every
 * sentence is tested in Node, in any language.
 * @typedef {{ [name: string]: (...args: any[]) => any }} PanelWords
 */

/**
 * What a panel's view gives its runs: its values and the hooks it is told by (each runs module
 * names its own hooks), with whatever else they drive (a GPU, a chain builder, a benchmark) as a
 * stand-in in Node.
 * @template [Hooks=object]
 * @template {Readonly<Values>} [V=Readonly<Values>]  the panel's values: ValuesOf<typeof schema>
 * @typedef {object} RunsOptions
 * @property {V} values  the host's live values, read at each call (never written: ctx.set is the view's)
 * @property {Hooks} [hooks]  what the view does when the state changes (a result arrived, a run started)
 */

/**
 * `runs.js` exports `create<Name>Runs(options)`: the panel's state apart from its DOM and its
 * values (what was read back, measured or built) and the runs that produce it, each taken from a
 * run gate (src/panels/shared/createRunGate.js) so a newer run, a lost context or dispose drops a
 * late result. It writes no sentence: a state or a cause is kept as data (an error, a code) and
 * words.js says it. No DOM, so it is tested in Node with stand-ins.
 * @typedef {object} PanelRuns
 * @property {(keys?: string[] | null) => unknown} update  the values changed (keys: which; none: all)
 * @property {() => void} dispose  cancels every run and frees what the runs own
 */

/**
 * @typedef {import('../panels/manifest.js').PanelEntry & {
 *   schema: Schema,
 *   mount?: (root: HTMLElement, ctx: PanelContext) => PanelInstance,
 *   load?: () => Promise<(root: HTMLElement, ctx: PanelContext) => PanelInstance>,
 * }} PanelDefinition  mount, or load() that resolves to it (the module arrives when the panel is first wanted)
 */

/**
 * The instance, if it keeps the contract; otherwise an error that names the panel and what is missing.
 * @param {string} id
 * @param {unknown} instance  what the panel's mount() returned
 * @returns {PanelInstance}
 */
export function checkInstance(id, instance) {
  /** @param {string} name */
  const member = (name) => (instance == null ? undefined : /** @type {Record<string, unknown>} */ (instance)[name]);
  const missing = ['update', 'describe', 'dispose'].filter((name) => typeof member(name) !== 'function');
  for (const name of ['csv', 'png']) {
    if (member(name) != null && typeof member(name) !== 'function') missing.push(`${name} (a function or null)`);
  }
  if (missing.length) throw new TypeError(`The ${id} panel's mount() returned no ${missing.join(', ')}.`);
  return /** @type {PanelInstance} */ (instance); // its members checked above
}
