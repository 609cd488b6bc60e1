// The deck author's reference of every panel's parameters, written when the docs are built
// (docs/.vitepress/config.js) from what the lab itself reads: the manifest (src/panels/manifest.js,
// in lecture order), each panel's schema (src/panels/<id>/schema.js) and the English catalogue's
// names of panels, controls and options (locales/en.json). Nothing in it is typed by hand, so it
// cannot drift from the code; a panel that has no section fails the docs build (missingSections).
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { pathToFileURL } from 'node:url';
import MessageFormat from '@messageformat/core';
import { PANELS } from '../src/panels/manifest.js';
import { plainText } from '../src/i18n/richText.js';

/** Where docs/deck/reference.md takes the generated sections. */
export const REFERENCE_MARKER = '<!-- panel parameters: written at docs build time by scripts/apiReference.js -->';

/**
 * What the reference is made of: the manifest's entries, each panel's schema by id, and the English
 * catalogue. Schemas are pure data that Node imports as they are.
 * @param {string} root  the project's folder
 */
export async function loadReferenceInputs(root, panels = PANELS) {
  const schemas = {};
  for (const { id } of panels) {
    const path = resolve(root, 'src/panels', id, 'schema.js');
    const module = await import(pathToFileURL(path).href).catch((error) => {
      throw new Error(`The panel “${id}” has no schema for the docs' reference (src/panels/${id}/schema.js): ${error.message}`);
    });
    schemas[id] = module.schema;
  }
  const english = JSON.parse(readFileSync(resolve(root, 'locales/en.json'), 'utf8'));
  return { panels, schemas, english };
}

const formats = new MessageFormat('en');
/** The English words at namespace.key as plain text (a message without arguments), or undefined. */
function words(english, namespace, key) {
  const table = english[namespace];
  if (!table || !Object.hasOwn(table, key)) return undefined;
  return plainText(formats.compile(table[key])({}));
}

// Markdown that shows text as written: inside a table cell and beside Vue's templates (the page
// wraps the sections in v-pre, so braces stay text).
const text = (value) => String(value).replace(/[\\`*_[\]<>|]/g, '\\$&');
const code = (value) => {
  const raw = String(value);
  if (raw.includes('`')) throw new Error(`A value with a backtick cannot be written in the reference: ${raw}`);
  return `\`${raw.replaceAll('|', '\\|')}\``;
};

/** The values a parameter takes, in words. */
function valuesOf(id, key, spec, english) {
  switch (spec.type) {
    case 'number': {
      const range = `${code(spec.min)} to ${code(spec.max)}`;
      const step = spec.integer ? 'whole numbers' : `step ${code(spec.step)}`;
      return `${range}, ${step}`;
    }
    case 'enum': {
      const options = Array.isArray(spec.options) ? spec.options.map(String) : Object.keys(spec.options);
      return options.map((value) => {
        const name = words(english, 'controls', `${id}.${key}.${value}`);
        return name && name !== value ? `${code(value)} (${text(name)})` : code(value);
      }).join(', ');
    }
    case 'boolean':
      return `${code('true')} or ${code('false')} (a link also takes ${code('1')} and ${code('0')})`;
    case 'color':
      return `${code('#rrggbb')} (a link writes it without ${code('#')})`;
    case 'text':
      return `text of at most ${code(spec.maxLength)} characters${spec.encode ? ', which a link holds in a compact form' : ''}`;
    default:
      throw new Error(`The panel “${id}” has a parameter “${key}” of a type the reference does not know: ${spec.type}.`);
  }
}

function defaultOf(spec, english) {
  if (spec.type === 'text' && spec.default === '') {
    const said = spec.defaultText ? words(english, 'host', `defaultText.${spec.defaultText}`) : undefined;
    return said ? `empty: ${text(said)}` : 'empty';
  }
  return code(spec.default);
}

/** One panel's section: its heading (anchored at its id), where its keys go, and a row per parameter. */
function panelSection(entry, schema, english) {
  const { id } = entry;
  if (!schema || typeof schema !== 'object') throw new Error(`The panel “${id}” has no schema for the docs' reference.`);
  const title = words(english, 'panels', `${id}.title`);
  if (!title) throw new Error(`The panel “${id}” has no title in locales/en.json (panels: “${id}.title”).`);
  const rows = Object.entries(schema).map(([key, spec]) => {
    const name = words(english, 'controls', `${id}.${key}`);
    if (!name) {
      throw new Error(`The panel “${id}” has no name for its control “${key}” in locales/en.json (controls: “${id}.${key}”).`);
    }
    const older = spec.aliases?.length ? ` (older: ${spec.aliases.map(code).join(', ')})` : '';
    return `| ${code(key)}${older} | ${text(name)} | ${spec.type} | ${defaultOf(spec, english)} | ${valuesOf(id, key, spec, english)} |`;
  });
  const example = Object.keys(schema)[0];
  const traits = [
    entry.webgl ? 'holds a WebGL context while it is shown' : 'draws without WebGL',
    ...(entry.animates ? [`its animation runs while ${code(entry.animates)} is on`] : []),
    ...(entry.material ? [`the page-wide material sets ${code(entry.material)}`] : []),
    ...(entry.materialSelect ? [`the page-wide material sets ${code(entry.materialSelect)}`] : []),
  ];
  return [
    `## ${text(title)} {#${id}}`,
    '',
    `${code(`embed.html?panel=${id}`)}; on the lecture page its keys are written `
      + `${code(`${entry.hero ? '' : `${id}.`}${example}=…`)}${entry.hero ? ' (the hero owns the short keys)' : ''}; `
      + `${traits.join('; ')}.`,
    '',
    '| key | control | type | default | values |',
    '|---|---|---|---|---|',
    ...rows,
  ].join('\n');
}

/**
 * The reference's sections, one per manifest entry in lecture order, wrapped so that Vue reads
 * them as plain HTML.
 * @param {{ panels: readonly { id: string, webgl: boolean, hero?: boolean, animates?: string,
 *   material?: string | null, materialSelect?: string }[], schemas: Record<string, object>, english: Record<string, any> }} inputs
 */
export function apiReference({ panels, schemas, english }) {
  const sections = panels.map((entry) => panelSection(entry, Object.hasOwn(schemas, entry.id) ? schemas[entry.id] : undefined, english));
  return ['<div v-pre>', '', sections.join('\n\n'), '', '</div>'].join('\n');
}

/**
 * The panels that have no section, in words ([] when every one has it). `hasSection(id)` reads the
 * reference where it is checked: its Markdown, or the page the docs build wrote.
 * @param {readonly string[]} ids
 * @param {(id: string) => boolean} hasSection
 */
export function missingSections(ids, hasSection) {
  return ids.filter((id) => !hasSection(id))
    .map((id) => `The panel “${id}” has no section in the parameter reference (docs/deck/reference.md).`);
}

/** Whether Markdown has a heading anchored at `id` ({#id}). */
export const markdownHasSection = (markdown, id) => markdown.split('\n').some((line) => /^## /.test(line) && line.endsWith(`{#${id}}`));

/** Whether a built page has a heading with the id `id`. */
export const htmlHasSection = (html, id) => new RegExp(`<h2 id="${id}"[ >]`).test(html);
