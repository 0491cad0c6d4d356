#!/usr/bin/env bash
# Where lavapipe's JIT-compiled shaders spend their time, instruction by instruction.
#   scripts/profile-jit.sh REQUEST.json [TOP]
# Renders the request with lpv-render under `perf record`, then again under gdb, stopped at
# the first vkDestroyPipeline (the shaders' machine code still mapped, at the same addresses:
# both runs have address randomisation off), disassembles the pages that got samples and
# prints (1) the samples by instruction mnemonic, (2) by range of adjacent code pages, which
# mostly tells functions apart, and (3) the TOP (default 8) hottest instructions with the code
# before them. perf cannot name JIT functions, so tell shaders apart by what the code does
# (or by profiling a request that runs only the pass you want).
# A sample lands on the instruction after the one that stalled, so each sample is counted
# for the instruction before it: `lock` heading the list means contended atomics, for example.
# Needs perf and gdb (developer tools, not in scripts/install-deps.sh) and a built lpv-render.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
request=${1:?usage: scripts/profile-jit.sh REQUEST.json [TOP]}
top=${2:-8}
for tool in perf gdb setarch python3; do
  command -v "$tool" >/dev/null || { echo "profile-jit.sh: needs $tool (Debian: linux-perf, gdb, util-linux, python3)" >&2; exit 2; }
done
[[ "$top" =~ ^[0-9]+$ ]] || { echo "profile-jit.sh: TOP must be a whole number, not '$top'" >&2; exit 2; }
[ -r "$request" ] || { echo "profile-jit.sh: cannot read $request" >&2; exit 2; }
bin="$root/build/lpv-render"
[ -x "$bin" ] || "$root/scripts/build.sh"
request=$(realpath "$request")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Both runs compile every shader cold (no Mesa shader cache, no pipeline cache), in the same
# order, so the JIT code lands at the same addresses in both.
export MESA_SHADER_CACHE_DISABLE=true LPV_PIPELINE_CACHE=off
if ! setarch -R perf record -q -o "$work/perf.data" "$bin" "$request" -o "$work/frame.png" >"$work/render.log" 2>&1 ||
  [ ! -s "$work/frame.png" ]; then
  echo "profile-jit.sh: the profiled render failed:" >&2
  cat "$work/render.log" >&2
  exit 1
fi
sed -n 1,2p "$work/render.log"  # what was profiled
# Samples as "count address": all of them, and those in JIT code (which perf, having no
# symbols for it, files under a /tmp/perf-PID.map it was never given).
perf script -i "$work/perf.data" -F ip,dso 2>/dev/null >"$work/script"
awk '{print $1}' "$work/script" | sort | uniq -c >"$work/samples"
awk '$2 ~ /perf-[0-9]+\.map/ {print $1}' "$work/script" | sort | uniq -c >"$work/jit-samples"

# Address ranges to disassemble: the JIT code pages holding at least 0.5% of the samples,
# neighbours merged (a range starting inside an instruction decodes wrongly for a few bytes).
python3 - "$work" <<'EOF' >"$work/ranges"
import sys
work = sys.argv[1]
total = sum(int(line.split()[0]) for line in open(f"{work}/samples"))
pages = {}
for c, a in (line.split() for line in open(f"{work}/jit-samples")):
    page = int(a, 16) & ~0xfff
    pages[page] = pages.get(page, 0) + int(c)
ranges = []
for page in sorted(p for p, c in pages.items() if c >= 0.005 * total):
    if ranges and ranges[-1][1] == page:
        ranges[-1][1] = page + 0x1000
    else:
        ranges.append([page, page + 0x1000])
for start, end in ranges:
    print(f"0x{start:x},0x{end:x}")
EOF
[ -s "$work/ranges" ] || { echo "profile-jit.sh: no samples in JIT code" >&2; exit 1; }
{
  echo "set pagination off"
  echo "set breakpoint pending on"
  echo "break vkDestroyPipeline"
  echo "run '$request' -o '$work/frame.png' >/dev/null"
  while read -r range; do echo "disassemble $range"; done <"$work/ranges"
  echo "kill"
} >"$work/gdb-commands"
gdb -q -batch -x "$work/gdb-commands" "$bin" >"$work/disassembly" 2>&1 || true

python3 - "$work" "$top" <<'EOF'
import collections, re, sys
work, top = sys.argv[1], int(sys.argv[2])
counts = {int(a, 16): int(c) for c, a in (line.split() for line in open(f"{work}/jit-samples"))}
total = sum(int(line.split()[0]) for line in open(f"{work}/samples"))
code = []  # (address, text) of every disassembled instruction, in address order
for line in open(f"{work}/disassembly"):
    m = re.match(r"\s*(?:=>\s*)?0x([0-9a-f]+)(?: <[^>]*>)?:\s+(.*)", line)
    if m:
        code.append((int(m.group(1), 16), m.group(2).strip()))
code.sort()
if not code:
    tail = "".join(open(f"{work}/disassembly").readlines()[-10:])
    sys.exit("profile-jit.sh: gdb disassembled nothing (did lpv-render destroy a pipeline?); gdb said:\n" + tail)
by_mnemonic = collections.Counter()
blamed = collections.Counter()  # index into code of the instruction each sample is counted for
for i in range(1, len(code)):
    c = counts.get(code[i][0], 0)
    if c and code[i][0] - code[i - 1][0] < 16:
        by_mnemonic[code[i - 1][1].split()[0]] += c
        blamed[i - 1] += c
jit = sum(by_mnemonic.values())
print(f"{total} samples, {jit} ({100 * jit / total:.0f}%) in the JIT code disassembled")
if jit < 0.5 * sum(counts.values()):
    print("warning: most JIT samples fell outside the disassembled instructions: the code may not be at "
          "the same addresses in the gdb run, so these shares are not to be trusted")
print("by instruction: " + "  ".join(f"{k} {100 * v / jit:.1f}%" for k, v in by_mnemonic.most_common(24)))
# Adjacent pages of JIT code are most often one function: a shader, or a function the shaders
# call (Mesa 25 calls one for every texel fetch, say), so a range's share tells them apart.
ranges = [tuple(int(x, 16) for x in line.split(",")) for line in open(f"{work}/ranges")]
in_range = collections.Counter()
for address, c in counts.items():
    for start, end in ranges:
        if start <= address < end:
            in_range[(start, end)] += c
ranged = sum(in_range.values())
print("by code range: " + "  ".join(f"0x{s:x}-0x{e:x} {100 * v / ranged:.0f}%" for (s, e), v in in_range.most_common(8)))
for i, c in blamed.most_common(top):
    print(f"\n{100 * c / total:.2f}% at 0x{code[i][0]:x}:")
    for j in range(max(0, i - 6), min(len(code), i + 2)):
        print(("  > " if j == i else "    ") + f"0x{code[j][0]:x}  {code[j][1]}")
EOF
