// One web engine's AO at many parameter sets, over several views of one scene, in one browser
// session (session.mjs, peers.js runEngine): what `ssaolab tune --engine` asks for each step of
// its search, then scores in-process against its reference.
//
// node run_engine.mjs --modules DIR    batches read from stdin, one JSON line each,
//     { "jobs": FILE, "out": DIR }, in one browser session; after each one the line
//     "ssaolab-batch-done" on stdout; the session ends with stdin. Every batch of a session has the
//     scene, size, page and views of its first (engine_runner.cpp keeps one session a runner).
// FILE: { scene (.gltf/.glb), width, height, page (peers.html, the default, or babylon.html: every
//         engine of one session runs on one page), peer (the page's name), params (rows of the engine's
//         table), views: [{ camera (metrics.json's), radius (R, scene units) }], frames,
//         jobs: [{ view, values: { name: value }, scale: { name: factor } (optional), image (file name),
//                  frames (optional), peer (optional: another engine, whose rows are tables[peer]),
//                  droppable (optional: a search's candidate, see jobLimit) }],
//         tables: { peer: params } (optional: the rows of each other engine the jobs name),
//         job_seconds: { frames: [seconds] } (optional: what the runner's earlier jobs took) }
// Writes each job's AO as DIR/IMAGE (binary PGM, top row first) and DIR/results.json:
// { renderer, three_revision, jobs: [{ image, values (what the pass ran with), frame_ms, plain_ms, ao_ms,
//   ao_ms_min, ao_ms_max, seconds (the job's wall time) }] }; each job's entry also as DIR/jN.json
// once it is done, and when the page hangs on job N past its time limit, DIR/hung.json { job: N }
// before it stops (the caller keeps what was done and runs the rest anew: engine_runner.cpp).
import fs from 'node:fs';
import path from 'node:path';
import readline from 'node:readline';
import { openSession, parseArgs, pgmBytes } from './session.mjs';

const args = parseArgs(process.argv, ['modules'], 'run_engine');
let session, first, current = -1, out = '';
const onLate = () => { if (current >= 0) fs.writeFileSync(path.join(out, 'hung.json'), JSON.stringify({ job: current })); };
const readSpec = (file) => JSON.parse(fs.readFileSync(file, 'utf8'));

// The session, opened on the first batch's scene, size, page and first view.
async function sessionFor(spec) {
    if (session) {
        for (const k of ['scene', 'width', 'height', 'page'])
            if (spec[k] !== first[k]) throw new Error(`a batch's ${k} differs from the session's`);
        return session;
    }
    first = spec;
    session = await openSession({ modules: args.modules, sceneFile: spec.scene, width: spec.width, height: spec.height,
                                  page: spec.page, camera: spec.views[0].camera, radius: spec.views[0].radius,
                                  tool: 'run_engine', onLate });
    return session;
}

// A droppable job's time limit (a search's candidate; any other job has the browser's whole limit,
// SSAOLAB_BROWSER_MAX_SECONDS, session.mjs): once 8 jobs with as many timed frames have run (in
// this session, or in the runner's earlier ones: the batch's job_seconds), 30 times their median
// (at least 10 s): a GL driver that hangs on one setting costs that, not the whole limit, and the
// tune goes on without it.
const spent = new Map(); // timed frames -> seconds each job took
function jobLimit(frames) {
    const s = [...(spent.get(frames) ?? [])].sort((a, b) => a - b);
    return s.length < 8 ? Infinity : Math.max(10, 30 * s[s.length >> 1]);
}

// One batch: every job's image, jN.json and, at the end, results.json in `dir`.
async function runBatch(spec, dir) {
    const { evaluate, setup } = await sessionFor(spec);
    for (const [frames, list] of Object.entries(spec.job_seconds ?? {}))
        if (!spent.has(Number(frames)) && Array.isArray(list)) spent.set(Number(frames), list.filter(Number.isFinite));
    out = dir;
    fs.mkdirSync(dir, { recursive: true });
    const results = { renderer: setup.renderer, three_revision: setup.three, jobs: new Array(spec.jobs.length) };
    // By view, so each view's passes are built once.
    const order = spec.jobs.map((_, i) => i).sort((a, b) => spec.jobs[a].view - spec.jobs[b].view || a - b);
    for (const i of order) {
        const job = spec.jobs[i], view = spec.views[job.view];
        const frames = job.frames ?? spec.frames ?? 0, start = performance.now();
        const limit = job.droppable ? jobLimit(frames) : Infinity; // session.mjs caps it at the browser's
        current = i; // a page that stops anywhere in this job's calls hung on it
        await evaluate(`view ${job.view}`, ([k, c, r]) => window.setEngineView(k, c, r),
                       [job.view, view.camera, view.radius], limit);
        const peer = job.peer ?? spec.peer, params = job.peer ? spec.tables[job.peer] : spec.params;
        const r = await evaluate(`job ${i}`, (j) => window.runEngine(j),
            { peer, params, values: job.values ?? {}, scale: job.scale ?? {}, frames },
            Math.max(1, limit - (performance.now() - start) / 1000));
        const seconds = (performance.now() - start) / 1000;
        if (!spent.has(frames)) spent.set(frames, []);
        spent.get(frames).push(seconds);
        fs.writeFileSync(path.join(dir, path.basename(job.image)), pgmBytes(r.ao, spec.width, spec.height));
        const { ao, ...rest } = r;
        results.jobs[i] = { image: path.basename(job.image), ...rest, seconds };
        fs.writeFileSync(path.join(dir, `j${i}.json`), JSON.stringify(results.jobs[i]));
        current = -1;
    }
    fs.writeFileSync(path.join(dir, 'results.json'), JSON.stringify(results, null, 1));
}

async function serve() {
    for await (const line of readline.createInterface({ input: process.stdin, crlfDelay: Infinity })) {
        if (!line.trim()) continue;
        const batch = JSON.parse(line);
        if (typeof batch.jobs !== 'string' || typeof batch.out !== 'string') throw new Error('a batch line needs jobs and out');
        await runBatch(readSpec(batch.jobs), batch.out);
        if (session.failed()) return; // the page's error is the last line on stderr; exit 1 below
        process.stdout.write('ssaolab-batch-done\n');
    }
}

let failed = false;
try {
    await serve();
} catch (e) {
    console.error(`run_engine: ${String(e.message ?? e).split('\n')[0]}`);
    failed = true;
} finally {
    if (session) await session.close();
}
process.exit(failed || session?.failed() ? 1 : 0);
