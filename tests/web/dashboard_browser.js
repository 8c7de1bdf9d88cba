// Drives chromium through the dashboard (tests/web/dashboard_browser.sh starts the servers and
// submits job 1, slow and named <script>alert(1)</script>, and job 2, a point-foot sweep).
// usage: node dashboard_browser.js BASE_URL CHROMIUM OUT_DIR; exits 1 on the first failed check.
"use strict";
const puppeteer = require("puppeteer-core");
const fs = require("fs");
const path = require("path");

const [base, chromium, outDir] = process.argv.slice(2);
const xssName = "<script>alert(1)</script>";
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
function check(ok, what) {
  if (!ok) throw new Error(what);
  console.log("ok: " + what);
}

async function main() {
  const browser = await puppeteer.launch({
    executablePath: chromium, headless: true,
    args: ["--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--no-first-run", "--no-proxy-server"],
  });
  const dialogs = [];
  const errors = [];
  const open = async (url) => {
    const page = await browser.newPage();
    await page.setViewport({ width: 1800, height: 900 });
    page.on("dialog", async (d) => { dialogs.push(d.message()); await d.dismiss(); });
    page.on("pageerror", (e) => errors.push(String(e)));
    page.on("console", (m) => { if (/Content.Security.Policy/i.test(m.text())) errors.push(m.text()); });
    await page.goto(url, { waitUntil: "domcontentloaded" });
    return page;
  };
  try {
    // Fleet: both jobs listed; the running one's progress rises.
    const fleet = await open(base + "/");
    await fleet.waitForFunction(() => document.querySelectorAll("#fleet tbody tr").length >= 2, { timeout: 15000 });
    const rowOf = (page, id) => page.$eval(`#fleet tbody tr[data-id="${id}"]`, (tr) => ({
      cells: [...tr.children].map((td) => td.textContent), state: tr.className,
      scripts: tr.querySelectorAll("script").length }));
    const percentOf = (row) => Number((row.cells[5].match(/(\d+)%/) || [0, -1])[1]);
    let first = await rowOf(fleet, 1);
    check(first.cells[1] === xssName, "the fleet shows job 1's name as text: " + first.cells[1]);
    check(first.scripts === 0, "no script element in job 1's row");
    await fleet.waitForFunction(() => {
      const tr = document.querySelector('#fleet tbody tr[data-id="1"]');
      return tr && tr.className === "running" && /\d+%/.test(tr.children[5].textContent);
    }, { timeout: 15000 });
    first = await rowOf(fleet, 1);
    const p0 = percentOf(first);
    await fleet.waitForFunction((p) => {
      const m = document.querySelector('#fleet tbody tr[data-id="1"]').children[5].textContent.match(/(\d+)%/);
      return m && Number(m[1]) > p;
    }, { timeout: 15000 }, p0);
    const p1 = percentOf(await rowOf(fleet, 1));
    check(p1 > p0, `job 1's progress rises on the fleet page without reload: ${p0}% -> ${p1}%`);
    const second = await rowOf(fleet, 2);
    check(second.cells[1] === "point-foot sweep", "the fleet lists job 2");

    // Job 2's page: a point lands in the result chart.
    const job = await open(base + "/job/2");
    await job.waitForFunction(() => Number(document.getElementById("result-chart").dataset.points) >= 1 &&
                                    document.querySelector("#result-chart canvas"), { timeout: 40000 });
    const points = await job.$eval("#result-chart", (e) => Number(e.dataset.points));
    check(points >= 1, `job 2's result chart has ${points} point(s)`);
    // A reload mid-job shows the same job again (state in the URL).
    await job.reload({ waitUntil: "domcontentloaded" });
    await job.waitForFunction(() => /Job 2: point-foot sweep/.test(document.getElementById("job-title").textContent),
                              { timeout: 10000 });
    check(true, "a reload of /job/2 shows job 2");
    await job.waitForFunction(() => Number(document.getElementById("result-chart").dataset.points) >= 2, { timeout: 40000 });
    await sleep(500);
    await job.screenshot({ path: path.join(outDir, "dashboard_job.png"), fullPage: false });

    // Job 1's page: the XSS name is inert there too; cancel works.
    const slow = await open(base + "/job/1");
    await slow.waitForFunction(() => document.getElementById("job-summary").dataset.state === "running", { timeout: 10000 });
    const title = await slow.$eval("#job-title", (e) => e.textContent);
    check(title === "Job 1: " + xssName, "job 1's title shows its name as text");
    // A hidden tab pauses its stream (docs/dashboard.md): shown again, the fleet catches up.
    await fleet.bringToFront();
    await fleet.waitForFunction(() => document.getElementById("connection").textContent === "live", { timeout: 5000 });
    await fleet.screenshot({ path: path.join(outDir, "dashboard_fleet.png"), fullPage: false });
    await slow.bringToFront();
    await slow.click("#cancel");
    await slow.waitForFunction(() => document.getElementById("job-summary").dataset.state === "cancelled", { timeout: 15000 });
    check(true, "the cancel button cancelled job 1: " + await slow.$eval("#cancel-answer", (e) => e.textContent));
    await fleet.bringToFront();
    await fleet.waitForFunction(() => document.querySelector('#fleet tbody tr[data-id="1"]').className === "cancelled",
                                { timeout: 5000 });
    check(true, "the fleet shows job 1 cancelled");

    // A job that does not exist: the page says so instead of waiting.
    const missing = await open(base + "/job/999");
    await missing.waitForFunction(() => /^refused/.test(document.getElementById("connection").textContent), { timeout: 5000 });
    check(true, "/job/999 says the stream was refused");
    await missing.close();

    // Job 2 done: its report shows inline, and a gait animation runs only while on screen (the
    // report's one script, allowed by its hash; a violation of the policy would be an error).
    await job.bringToFront();
    await job.waitForFunction(() => document.getElementById("job-summary").dataset.state === "done", { timeout: 60000 });
    const frame = await (await job.waitForSelector("iframe.report", { timeout: 10000 })).contentFrame();
    await frame.waitForFunction(() => document.querySelectorAll("figure>svg animate").length > 0, { timeout: 30000 });
    const animations = () => frame.evaluate(() => {
      const svgs = [...document.querySelectorAll("figure>svg")].filter((s) => s.querySelector("animate"));
      return { all: svgs.length, paused: svgs.filter((s) => s.animationsPaused()).length, last: svgs[svgs.length - 1].animationsPaused() };
    });
    const before = await animations();
    check(before.paused > 0 && before.last, `job 2's report: ${before.paused} of ${before.all} gait animations paused off screen`);
    await job.evaluate(() => document.querySelector("iframe.report").scrollIntoView());
    await frame.evaluate(() => [...document.querySelectorAll("figure>svg")].filter((s) => s.querySelector("animate")).pop().scrollIntoView());
    await frame.waitForFunction(() => !document.querySelectorAll("figure>svg")[document.querySelectorAll("figure>svg").length - 1].animationsPaused(),
                                { timeout: 5000 });
    check(true, "the last gait animation runs once it is on screen");

    // Latency from a progress message's timestamp to its showing on the page.
    const latencies = (await fleet.evaluate(() => window.cycloptShownLatencyMs))
      .concat(await job.evaluate(() => window.cycloptShownLatencyMs)).sort((a, b) => a - b);
    const q = (f) => latencies[Math.min(latencies.length - 1, Math.floor(f * latencies.length))];
    const summary = `progress message -> page: ${latencies.length} messages, median ${q(0.5).toFixed(1)} ms, ` +
                    `p95 ${q(0.95).toFixed(1)} ms, max ${latencies[latencies.length - 1].toFixed(1)} ms`;
    fs.writeFileSync(path.join(outDir, "dashboard_latency.txt"), summary + "\n");
    check(latencies.length > 0 && q(0.95) <= 1000, summary);
    check(dialogs.length === 0, "no dialog opened (" + dialogs.join(", ") + ")");
    check(errors.length === 0, "no script error on the pages (" + errors.join("; ") + ")");
  } finally {
    await browser.close();
  }
}

main().catch((e) => { console.error("FAIL: " + e.message); process.exit(1); });
