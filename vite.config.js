import { defineConfig } from 'vite';
import { readdirSync, existsSync, readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { PANELS, SECTIONS_MARKER, manifestProblems, sectionHtml } from './src/panels/manifest.js';

const root = import.meta.dirname;

/** Panel folders that hold a module (src/panels/<id>/index.js). */
function panelFolders() {
  const dir = resolve(root, 'src/panels');
  return readdirSync(dir, { withFileTypes: true })
    .filter((d) => d.isDirectory() && existsSync(resolve(dir, d.name, 'index.js')))
    .map((d) => d.name);
}

/**
 * The lecture page's sections come from the panel manifest: written into index.html at build
 * (and dev) time, so the page is readable before any script runs. The build fails when the
 * manifest, the panel folders and the page disagree.
 */
function panelManifest() {
  const check = () => {
    const problems = manifestProblems(panelFolders(), readFileSync(resolve(root, 'index.html'), 'utf8'));
    if (problems.length) throw new Error(`Panel manifest (src/panels/manifest.js):\n  ${problems.join('\n  ')}`);
  };
  return {
    name: 'fresnel-lab-panel-manifest',
    buildStart: check,
    transformIndexHtml: {
      order: 'pre',
      handler(html, { filename }) {
        if (!filename.endsWith('index.html') || filename.endsWith('embed.html')) return html;
        check();
        return html.replace(SECTIONS_MARKER, PANELS.map(sectionHtml).join('\n\n    '));
      },
    },
  };
}

// Relative base: the built site works from any sub-path (a course page, a USB stick).
export default defineConfig({
  base: './',
  plugins: [panelManifest()],
  build: {
    target: 'es2022',
    // three.js's WebGLRenderer is most of the normal-map viewer's chunk; only that panel loads it.
    chunkSizeWarningLimit: 700,
    rollupOptions: {
      input: {
        index: resolve(root, 'index.html'),
        embed: resolve(root, 'embed.html'),
        // npm run bench also builds the three.js peer the hero is measured against (not shipped).
        ...(process.env.FRESNEL_LAB_BENCH_PEER === '1' ? { peer: resolve(root, 'bench/peer.html') } : {}),
      },
    },
  },
  server: { host: '127.0.0.1' },
  preview: { host: '127.0.0.1' },
  test: {
    include: ['tests/unit/**/*.test.js'],
    environment: 'node',
  },
});
