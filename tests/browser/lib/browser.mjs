// Debian's Chromium, headless, driven through the DevTools protocol by puppeteer-core (which never
// downloads a browser). Audio runs (the AudioWorklet renders) but is muted.
import puppeteer from 'puppeteer-core';

export const chromiumPath = process.env.VIMG_CHROMIUM || '/usr/bin/chromium';

export async function launchBrowser() {
  return puppeteer.launch({
    executablePath: chromiumPath,
    headless: true,
    args: ['--no-sandbox', '--autoplay-policy=no-user-gesture-required', '--mute-audio',
           '--disable-gpu', '--window-size=1200,900'],
    defaultViewport: { width: 1200, height: 900 },
  });
}

// A page that records every console error and uncaught exception.
export async function openPage(browser, url) {
  const page = await browser.newPage();
  const problems = [];
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console.error: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`uncaught: ${e.message}`));
  page.on('requestfailed', (r) => problems.push(`request failed: ${r.url()} ${r.failure()?.errorText}`));
  page.on('response', (r) => { if (r.status() >= 400) problems.push(`HTTP ${r.status()}: ${r.url()}`); });
  await page.goto(url, { waitUntil: 'load' });
  await page.waitForFunction(() => window.vimg !== undefined && window.vimg.ready !== undefined, { timeout: 60000 });
  await page.evaluate(() => window.vimg.ready);
  return { page, problems };
}
