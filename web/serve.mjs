// serve.mjs — a static file server for the built page (build-web/site), for local use and tests.
//
//   node web/serve.mjs [FOLDER] [PORT]      serves FOLDER (default build-web/site) on 127.0.0.1
//
// Only files inside FOLDER are served; the listening address is printed on stdout.
import http from 'node:http';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const types = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.mjs': 'text/javascript',
  '.wasm': 'application/wasm', '.data': 'application/octet-stream', '.json': 'application/json',
  '.png': 'image/png', '.glb': 'model/gltf-binary', '.gltf': 'model/gltf+json',
};

export function serve(folder, port = 0) {
  const root = fs.realpathSync(folder);
  const server = http.createServer((request, response) => {
    const url = new URL(request.url, 'http://localhost');
    let file = path.join(root, decodeURIComponent(url.pathname));
    if (file.endsWith(path.sep)) file = path.join(file, 'index.html');
    let real;
    try { real = fs.realpathSync(file); } catch { real = null; }
    if (!real || !(real === root || real.startsWith(root + path.sep)) || !fs.statSync(real).isFile()) {
      response.writeHead(404, { 'content-type': 'text/plain' }).end('not found\n');
      return;
    }
    response.writeHead(200, { 'content-type': types[path.extname(real)] || 'application/octet-stream',
                              'cache-control': 'no-store' });
    fs.createReadStream(real).pipe(response);
  });
  return new Promise((resolve) => server.listen(port, '127.0.0.1', () => resolve(server)));
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const folder = process.argv[2] || 'build-web/site';
  const server = await serve(folder, Number(process.argv[3] || 8000));
  const { port } = server.address();
  console.log(`Serving ${folder} at http://127.0.0.1:${port}/ (Ctrl+C stops)`);
}
