// One browser session for the web peers: a local HTTP server for the npm packages, this folder and
// the scene's folder, and Debian's Chromium (headless, WebGL through ANGLE on the machine's GL: Mesa
// llvmpipe without a GPU, the same rasteriser ssaolab's EGL context gets) with peers.html loaded
// and the scene set up. run_peers.mjs (make peers) and run_engine.mjs (ssaolab tune --engine) share it.
import http from 'node:http';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const types = { '.js': 'text/javascript', '.mjs': 'text/javascript', '.html': 'text/html', '.json': 'application/json',
                '.gltf': 'model/gltf+json', '.glb': 'model/gltf-binary', '.bin': 'application/octet-stream',
                '.png': 'image/png', '.jpg': 'image/jpeg', '.jpeg': 'image/jpeg', '.ktx2': 'image/ktx2' };

// Arguments as --key value pairs.
export function parseArgs(argv, need, tool) {
    const args = {};
    for (let i = 2; i < argv.length; i += 2) args[argv[i].replace(/^--/, '')] = argv[i + 1];
    for (const k of need) if (!args[k]) { console.error(`${tool}: missing --${k}`); process.exit(2); }
    return args;
}

// The rows of a GL read (bottom-up) as a binary PGM (top-down), one byte per pixel.
export function pgmBytes(aoBase64, width, height) {
    const ao = Buffer.from(aoBase64, 'base64');
    const flipped = Buffer.alloc(ao.length);
    for (let y = 0; y < height; ++y) ao.copy(flipped, (height - 1 - y) * width, y * width, (y + 1) * width);
    return Buffer.concat([Buffer.from(`P5\n${width} ${height}\n255\n`), flipped]);
}

// Opens the session; `camera` is ssaolab's metrics.json camera of the first view, `radius` R in
// scene units. Returns { page, setup, failed(), close() }.
export async function openSession({ modules, sceneFile, width, height, camera, radius, tool }) {
    modules = path.resolve(modules);
    sceneFile = path.resolve(sceneFile);
    const { chromium } = await import(path.join(modules, 'playwright-core', 'index.mjs'));
    const roots = { three: path.join(modules, 'three'), n8ao: path.join(modules, 'n8ao'),
                    postprocessing: path.join(modules, 'postprocessing'), page: here,
                    scene: path.dirname(sceneFile) };
    const server = http.createServer((req, res) => {
        const url = decodeURIComponent(new URL(req.url, 'http://x').pathname);
        if (url === '/favicon.ico') { res.writeHead(204); res.end(); return; }
        const [, root, ...rest] = url.split('/');
        const base = roots[root];
        const file = base && path.resolve(base, rest.join('/'));
        if (!file || !file.startsWith(base) || !fs.existsSync(file) || fs.statSync(file).isDirectory()) {
            res.writeHead(404); res.end(); return;
        }
        res.writeHead(200, { 'content-type': types[path.extname(file).toLowerCase()] ?? 'application/octet-stream' });
        fs.createReadStream(file).pipe(res);
    });
    await new Promise((r) => server.listen(0, '127.0.0.1', r));
    const port = server.address().port;
    let browser;
    try {
        browser = await chromium.launch({
            executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
            args: ['--use-gl=angle', '--use-angle=gl-egl', '--ignore-gpu-blocklist', '--enable-gpu',
                   '--disable-gpu-vsync', '--disable-frame-rate-limit', '--no-sandbox'],
        });
    } catch (e) {
        server.close();
        throw e;
    }
    let failed = false;
    const close = async () => { await browser.close(); server.close(); };
    try {
        const page = await browser.newPage({ viewport: { width, height } });
        page.on('pageerror', (e) => { console.error(`${tool}: page error: ${e.message}`); failed = true; });
        page.on('console', (m) => { if (m.type() === 'error') console.error(`${tool}: ${m.text()}`); });
        await page.goto(`http://127.0.0.1:${port}/page/peers.html`);
        await page.waitForFunction(() => window.peersReady === true, null, { timeout: 60000 });
        const setup = await page.evaluate((c) => window.setupPeers(c), {
            scene: `/scene/${encodeURIComponent(path.basename(sceneFile))}`, width, height, radius, camera });
        return { page, setup, failed: () => failed, close };
    } catch (e) {
        await close();
        throw e;
    }
}
