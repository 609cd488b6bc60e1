import { defineConfig } from '@playwright/test';
import { execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { register } from 'node:module';

// A spec may import the lab's modules, and with them the message catalogues' virtual modules.
register('./tests/e2e/messagesHooks.js', import.meta.url);

// One free loopback port, chosen once: workers inherit it through the environment.
if (!process.env.FRESNEL_LAB_PORT) {
  const probe = "const s=require('net').createServer().listen(0,'127.0.0.1',()=>{console.log(s.address().port);s.close()})";
  process.env.FRESNEL_LAB_PORT = execFileSync(process.execPath, ['-e', probe]).toString().trim();
}
const port = Number(process.env.FRESNEL_LAB_PORT);

// CHROMIUM_PATH, else Debian's chromium, else Playwright's own browser if one is installed.
const executablePath = process.env.CHROMIUM_PATH || (existsSync('/usr/bin/chromium') ? '/usr/bin/chromium' : undefined);

/**
 * For the tests alone, not the benchmark (bench/run.js leaves them out): the page compositor in
 * software rather than through SwiftShader's Vulkan. On two cores the same specs ran in about three
 * quarters of the time (embeds and asphalt 96 s against 129 s). WebGL still renders with SwiftShader.
 */
export const TEST_ONLY_ARGS = ['--disable-gpu-compositing'];

export default defineConfig({
  testDir: 'tests/e2e',
  // The smoke pass (npm run test:smoke) repeats what the full suite checks more closely: only on its own.
  testIgnore: process.env.FRESNEL_LAB_SMOKE ? [] : ['**/smoke.spec.js'],
  timeout: 90_000,
  expect: { timeout: 20_000 },
  workers: 1, // SwiftShader renders on the CPU; parallel pages only slow each other down
  reporter: process.env.CI ? [['list']] : [['list']],
  use: {
    baseURL: `http://127.0.0.1:${port}/`,
    viewport: { width: 1280, height: 800 },
    launchOptions: {
      executablePath,
      args: [
        '--use-angle=swiftshader',
        '--enable-unsafe-swiftshader',
        '--ignore-gpu-blocklist',
        '--no-sandbox',
        '--disable-background-networking',
        '--disable-component-update',
        '--disable-sync',
        '--no-first-run',
        ...TEST_ONLY_ARGS,
      ],
    },
  },
  // The built site by default (what users get); FRESNEL_LAB_DEV=1 serves the sources instead.
  webServer: {
    command: process.env.FRESNEL_LAB_DEV
      ? `npx vite --host 127.0.0.1 --port ${port} --strictPort`
      : `npx vite preview --host 127.0.0.1 --port ${port} --strictPort`,
    url: `http://127.0.0.1:${port}/`,
    reuseExistingServer: false,
    timeout: 60_000,
  },
});
