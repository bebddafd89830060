// Starts `isopatch view ...` on a free port and returns its URL (the first line it prints) and a stop().
import { spawn } from 'node:child_process';
import { createInterface } from 'node:readline';

export function cliPath() {
  const cli = process.env.ISOPATCH_CLI;
  if (!cli) throw new Error('set ISOPATCH_CLI to the isopatch binary (ctest does)');
  return cli;
}

export async function startViewer(args, timeoutMs = 60000) {
  const child = spawn(cliPath(), ['view', ...args, '--port', '0'], { stdio: ['ignore', 'pipe', 'pipe'] });
  let stderr = '';
  child.stderr.on('data', (d) => { stderr += d; });
  const lines = createInterface({ input: child.stdout });
  const url = await new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`no URL within ${timeoutMs} ms; stderr: ${stderr}`)), timeoutMs);
    lines.once('line', (line) => { clearTimeout(timer); resolve(line.trim()); });
    child.once('exit', (code) => { clearTimeout(timer); reject(new Error(`isopatch view exited (${code}): ${stderr}`)); });
  });
  const exited = new Promise((resolve) => child.once('exit', (code, signal) => resolve({ code, signal })));
  return {
    url,
    child,
    stderr: () => stderr,
    async stop() {
      child.kill('SIGINT');
      return exited;
    },
  };
}
