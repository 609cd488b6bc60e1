import { describe, expect, test } from 'vitest';
import { createHash } from 'node:crypto';
import { contentSecurityPolicy, hashSource, inlineTexts, withPolicyMeta } from '../../scripts/contentSecurityPolicy.js';

const directives = (policy) => Object.fromEntries(policy.split('; ').map((d) => { const [name, ...s] = d.split(' '); return [name, s]; }));

describe('the pages\' Content-Security-Policy', () => {
  test('a served page loads script, style, fonts and workers from its own origin only, nothing inline', () => {
    const d = directives(contentSecurityPolicy({}));
    expect(d['default-src']).toEqual(["'none'"]);
    expect(d['script-src']).toEqual(["'self'"]);
    expect(d['style-src']).toEqual(["'self'"]);
    expect(d['worker-src']).toEqual(["'self'"]);
    expect(d['font-src']).toEqual(["'self'", 'data:']);
    expect(d['base-uri']).toEqual(["'none'"]);
    expect(contentSecurityPolicy({})).not.toMatch(/unsafe|\*|https?:|frame-ancestors|report-uri|sandbox/);
  });

  test('a single-file page allows exactly its inline script and style, by hash, and no file', () => {
    const d = directives(contentSecurityPolicy({ singleFile: true, scripts: ['run()'], styles: ['p{}'] }));
    expect(d['script-src']).toEqual([hashSource('run()')]);
    expect(d['style-src']).toEqual([hashSource('p{}')]);
    expect(d['worker-src']).toEqual(['blob:']);
    expect(d['font-src']).toEqual(['data:']);
    expect(d['connect-src']).toEqual(["'none'"]);
    expect(directives(contentSecurityPolicy({ singleFile: true }))['script-src']).toEqual(["'none'"]);
  });

  test('a hash is the base64 SHA-256 of the text as UTF-8', () => {
    const text = 'const n = "n\u1d62";\n';
    expect(hashSource(text)).toBe(`'sha256-${createHash('sha256').update(Buffer.from(text, 'utf8')).digest('base64')}'`);
  });

  test('inline scripts and styles are found; files and data blocks are not scripts to allow', () => {
    const html = '<head><script type="module" crossorigin>a()</script><script src="x.js"></script><style rel="stylesheet">p{}</style></head>'
      + '<body><script>b()</script><script type="application/json" id="sheet">{"a":1}</script></body>';
    expect(inlineTexts(html)).toEqual({ scripts: ['a()', 'b()'], styles: ['p{}'] });
  });

  test('the meta goes at the top of <head>, after the charset and before any script, once', () => {
    const html = '<!doctype html><html><head>\n  <meta charset="utf-8"><script src="a.js"></script></head></html>';
    const out = withPolicyMeta(html, "script-src 'self'");
    expect(out.indexOf('http-equiv="Content-Security-Policy"')).toBeLessThan(out.indexOf('<script'));
    expect(out.indexOf('http-equiv="Content-Security-Policy"')).toBeGreaterThan(out.indexOf('charset'));
    expect(out).toContain(`content="script-src 'self'"`);
    expect(() => withPolicyMeta(out, "script-src 'self'")).toThrow(/already/);
    expect(() => withPolicyMeta('<p>no head</p>', 'x')).toThrow(/no <head>/);
  });
});
