// Shared browser-test fixture: fails a test on any console error or page error, and logs the
// WebGL renderer string once per run so every report says what it ran on.
import { test as base, expect } from '@playwright/test';

let rendererLogged = false;

export const test = base.extend({
  page: async ({ page }, use) => {
    const problems = [];
    page.on('console', (message) => {
      if (message.type() === 'error') problems.push(`console error: ${message.text()}`);
    });
    page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
    await use(page);
    expect(problems, 'the page logged errors').toEqual([]);
  },
});

/** Opens a page, waits for its panels, and logs the WebGL renderer once. */
export async function openLab(page, path = './') {
  await page.goto(path);
  await page.evaluate(() => window.fresnelLab.ready);
  if (!rendererLogged) {
    rendererLogged = true;
    const renderer = await page.evaluate(() => {
      const gl = document.createElement('canvas').getContext('webgl2');
      if (!gl) return 'no WebGL2';
      const info = gl.getExtension('WEBGL_debug_renderer_info');
      return `${gl.getParameter(gl.VERSION)} | ${info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER)}`;
    });
    console.log(`[webgl] ${renderer}`);
  }
}

export { expect };
