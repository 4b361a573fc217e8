// Every browser suite in one node process and one Chromium (browser.mjs): what CTest runs,
//   node --test --test-concurrency=1 tests/web/all.mjs
import './view.test.mjs';
import './serve.test.mjs';
