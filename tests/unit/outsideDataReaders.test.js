// The readers of outside data that checkStrictFiles.js holds to the strict type check: each way in
// is found in a module's code, and what is not a way in (a comment, a worker's own messages, the
// page's own editor) is not.
import { describe, expect, test } from 'vitest';
import { waysIn } from '../../scripts/outsideDataReaders.js';

describe('waysIn: the ways outside data enters a module', () => {
  test.each([
    ['const code = localStorage.getItem(KEY);', ['web storage']],
    ['sessionStorage.setItem(KEY, JSON.stringify(results));', ['web storage']],
    ['const saved = JSON.parse(raw);', ['JSON.parse']],
    ["const link = new URLSearchParams(window.location.search).get('lang');", ['the link']],
    ['if (window.location.hash !== `#${id}`) go(id);', ['the link']],
    ["window.addEventListener('message', onMessage);", ['messages from other windows']],
    ['const reader = new FileReader();', ['files and pasted or dropped data']],
    ['dropped = await fromDrop(event.dataTransfer);', ['files and pasted or dropped data']],
    ['return { ok: true, text: await file.text() };', ['a file or response body']],
    ['response.json().then(show);', ['a file or response body']],
    ["const response = await fetch(`offline/${name}`);", ['the network']],
    ["const binary = atob(code.replace(/-/g, '+'));", ['a decoder of packed text']],
    ["import { inflateSync } from 'fflate';", ['a decoder of packed text']],
    ["const stream = blob.stream().pipeThrough(new DecompressionStream('deflate-raw'));", ['a decoder of packed text']],
    ["const saved = JSON.parse(localStorage.getItem(KEY) ?? '{}');", ['web storage', 'JSON.parse']],
  ])('%s', (code, expected) => {
    expect(waysIn(code)).toEqual(expected);
  });

  test.each([
    ['a comment', '// kept in localStorage, read with JSON.parse\n/* new URLSearchParams(location.search) */\nconst a = 1;'],
    ["a worker's own messages", 'self.onmessage = ({ data }) => { post(data); };\nworker.onmessage = (event) => done(event.data);'],
    ["the page's own editor", "submit(editor.text());\nconst same = editor.text() === start;"],
    ['a message sent', "window.parent.postMessage({ type: 'fresnel-lab:loading' }, origin);"],
    ['text written', 'navigator.clipboard.writeText(code);'],
  ])('none in %s', (_what, code) => {
    expect(waysIn(code)).toEqual([]);
  });

  test('a URL in a string is code, not a comment', () => {
    expect(waysIn("const home = 'https://example.org/'; const kept = sessionStorage.length;")).toEqual(['web storage']);
  });
});
