// Requests against cyclopt-web under authentication (tests/web/dashboard_auth.sh submitted job 1
// with alice's key). usage: node dashboard_auth.js BASE ALICE BOB ROOT ALICE_EXPIRING
"use strict";
const [base, alice, bob, root, expiring] = process.argv.slice(2);
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
function check(ok, what) {
  if (!ok) throw new Error(what);
  console.log("ok: " + what);
}
// The cookie the login sets, as a browser would keep it.
async function login(token) {
  const r = await fetch(base + "/login?token=" + encodeURIComponent(token), { redirect: "manual" });
  const cookie = (r.headers.get("set-cookie") || "").split(";")[0];
  return { status: r.status, cookie, flags: r.headers.get("set-cookie") || "" };
}
const get = (path, cookie) => fetch(base + path, { headers: cookie ? { Cookie: cookie } : {}, redirect: "manual" });
// The first "rows" event of the fleet stream.
async function fleetRows(cookie) {
  const r = await get("/api/fleet/events", cookie);
  const reader = r.body.getReader();
  let text = "";
  while (!/\n\n/.test(text)) text += new TextDecoder().decode((await reader.read()).value);
  reader.cancel();
  return JSON.parse(text.match(/^data: (.*)$/m)[1]);
}
const cancel = (cookie, headers) => fetch(base + "/api/job/1/cancel",
                                           { method: "POST", headers: Object.assign({ Cookie: cookie }, headers) });

async function main() {
  check((await get("/")).status === 401, "the page needs a login");
  check((await get("/api/fleet/events")).status === 401, "the fleet stream needs a login");
  check((await get("/job/1/export.json")).status === 401, "the export needs a login");
  check((await get("/static/dashboard.js")).status === 200, "the static files are served without one");
  check((await login("alice.9999999999.00")).status === 401, "a forged token is refused");
  await sleep(1500);
  check((await login(expiring)).status === 401, "an expired token is refused");
  const a = await login(alice), b = await login(bob), r = await login(root);
  check(a.status === 303 && /HttpOnly/.test(a.flags) && /SameSite=Strict/.test(a.flags), "alice logs in: " + a.flags);
  check((await get("/", a.cookie)).status === 200, "alice sees the page");
  check((await fleetRows(a.cookie)).some((row) => row.id === 1), "alice's fleet lists her job");
  let live = false;  // progress messages are signed with alice's key: cyclopt-web checks them with the key file
  for (let i = 0; i < 50 && !live; ++i, await sleep(100)) live = (await fleetRows(a.cookie)).some((row) => row.progress_us > 0);
  check(live, "alice's job shows live progress (signed messages verified)");
  check((await fleetRows(b.cookie)).length === 0, "bob's fleet does not list alice's job (auth_reads owner)");
  check((await fleetRows(r.cookie)).some((row) => row.id === 1), "the admin key's fleet lists it");
  check((await get("/job/1/export.json", b.cookie)).status === 404, "bob cannot export alice's job");
  check((await get("/api/job/1/cancel", a.cookie)).status === 404, "no cancel through GET");
  check((await cancel(a.cookie, {})).status === 403, "a cancel without the dashboard's header is refused");
  check((await cancel(a.cookie, { "X-Cyclopt-Action": "cancel", Origin: "http://evil.example" })).status === 403,
        "a cancel from another origin is refused");
  check((await cancel(b.cookie, { "X-Cyclopt-Action": "cancel" })).status === 404, "bob cannot cancel alice's job");
  const answer = await (await cancel(a.cookie, { "X-Cyclopt-Action": "cancel" })).json();
  check(answer.ok === true, "alice cancels her job through the dashboard: " + answer.message);
}
main().catch((e) => { console.error("FAIL: " + e.message); process.exit(1); });
