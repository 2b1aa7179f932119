// Starts the real `vimg serve` and waits for the URL it prints (never for a fixed time).
import { spawn } from 'node:child_process';

export async function startServe(vimg, args, { log = () => {} } = {}) {
  const child = spawn(vimg, ['serve', ...args, '--port', '0'], { stdio: ['ignore', 'pipe', 'pipe'] });
  let stdout = '';
  let stderr = '';
  child.stderr.on('data', (d) => { stderr += d; log(String(d)); });
  const url = await new Promise((resolve, reject) => {
    const hang = setTimeout(() => reject(new Error(`vimg serve printed no URL within 60 s:\n${stdout}\n${stderr}`)), 60000);
    child.stdout.on('data', (d) => {
      stdout += d;
      const m = stdout.match(/http:\/\/127\.0\.0\.1:\d+\/?/);
      if (m) { clearTimeout(hang); resolve(m[0].endsWith('/') ? m[0] : `${m[0]}/`); }
    });
    child.on('exit', (code) => { clearTimeout(hang); reject(new Error(`vimg serve exited ${code}:\n${stdout}\n${stderr}`)); });
  });
  return {
    url,
    child,
    stderr: () => stderr,
    // SIGTERM: the server must stop cleanly with 143.
    async stop() {
      if (child.exitCode !== null) return child.exitCode;
      const exited = new Promise((resolve) => child.on('exit', (code, signal) => resolve(code ?? signal)));
      child.kill('SIGTERM');
      return exited;
    },
  };
}
