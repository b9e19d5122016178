#!/usr/bin/env bash
# The machine configuration is validated as a whole by every command (issue
# 22 §2, docs/MACHINE-CONFIG.md): a value that used to switch a travel limit
# off, a file cut off, a binary file, a folder or FIFO given as --machine are
# refused with exit 2 by check, compile, md, run and restart alike, naming
# file, line, key, value and range, without raw bytes on the terminal.
source "$(dirname "$0")/common.bash"
export XDG_STATE_HOME="$TEST_TMP/state"
cd "$TEST_TMP" || exit 1
demo="$MTC_SOURCE_DIR/resources/machines/demo-cell.cfg"

# Every command with the configuration `$1`; each must refuse with exit 2.
each_command_refuses() {
  local cfg="$1" what="$2" pattern="$3"
  for command in "check 1" "compile 1" "run 1" "restart 1 --target N0010" "md get 30" \
                 "md set 60 5 1"; do
    # shellcheck disable=SC2086
    expect_rc 2 "$what: $command" --machine "$cfg" $command
    text_check "$what: $command names it" "$pattern"
  done
}

# min = nan switched the software limit of X off (X ran to 5000 mm, status ok).
line=$(grep -n '^min = -400' "$demo" | head -1 | cut -d: -f1)
sed "${line}s/.*/min = nan/" "$demo" >nan.cfg
each_command_refuses nan.cfg "min = nan" "line $line: nan.cfg: \[process 0 axis X\] min = 'nan' is not a number.*allowed: -1000000 … 1000000 mm"
sed "${line}s/.*/max = inf/;$((line + 1))d" "$demo" >inf.cfg
expect_rc 2 "max = inf" --machine inf.cfg run 1
text_check "max = inf named" "max = 'inf'"
for bad in "max_velocity = 1e-320" "max_velocity = 0x10" "max_velocity = 5,5" "max_velocity =" \
           "max_velocity = 1e308"; do
  vline=$(grep -n '^max_velocity = 30000' "$demo" | head -1 | cut -d: -f1)
  sed "${vline}s/.*/$bad/" "$demo" >velocity.cfg
  expect_rc 2 "$bad" --machine velocity.cfg check 1
  text_check "$bad: line and range" "line $vline: velocity.cfg: .*max_velocity.*allowed: 1 … 10000000 mm/min"
done
for bad in "B015 = 5,5" "B033 = abc" "B036 =" "B058 = nan" "B062 = maybe" "B099 = yes"; do
  bline=$(grep -n '^B015 = radius' "$demo" | head -1 | cut -d: -f1)
  sed "${bline}s/.*/$bad/" "$demo" >parameter.cfg
  expect_rc 2 "$bad" --machine parameter.cfg md get 30
  text_check "$bad: its line" "line $bline: parameter.cfg"
done

# Duplicates, tools and offsets.
sed 's/^G54 = X-150 Y-80 Z-120/G54 = X1e308 Y-80 Z-120/' "$demo" >offset.cfg
expect_rc 2 "G54 X1e308" --machine offset.cfg run 1
sed 's/^T1 = radius 3.5 length 82.5 name mill1/T1 =/' "$demo" >tool.cfg
expect_rc 2 "empty T1" --machine tool.cfg check 1
sed 's/^T2 = radius 5 /T2 = radius nan /' "$demo" >radius.cfg
expect_rc 2 "radius nan" --machine radius.cfg compile 1
sed 's/^B004 = 17 .*/B004 = 17\nB004 = 18/' "$demo" >twice.cfg
expect_rc 2 "a key twice" --machine twice.cfg run 1
text_check "duplicate named" "CFG_DUPLICATE"

# A file cut off in the middle of a number: max_velocity = 3000 left of 30000.
cut_at=$(grep -b -o 'max_velocity = 30000' "$demo" | tail -1 | cut -d: -f1)
head -c $((cut_at + 19)) "$demo" >cut.cfg
expect_rc 2 "cut off in a number" --machine cut.cfg run 1
text_check "truncation named" "CFG_TRUNCATED"
grep -v '^\[end\]' "$demo" >noend.cfg
expect_rc 2 "no end marker" --json --machine noend.cfg check 1
json_check "truncation in JSON" 'any(x["code"] == "CFG_TRUNCATED" for x in d["diagnostics"])'

# Binary garbage: refused, and nothing but printable text reaches the terminal.
python3 -c 'import random, sys; random.seed(22); sys.stdout.buffer.write(bytes(random.randrange(256) for _ in range(4000)))' >garbage.cfg
printf '\033[2J\007[process 0]\nname = \033]0;owned\007\n' >>garbage.cfg
for format in "" "--json"; do
  # shellcheck disable=SC2086
  expect_rc 2 "binary garbage $format" $format --machine garbage.cfg check 1
  if cat "$TEST_TMP/out" "$TEST_TMP/err" | python3 -c '
import sys
d = sys.stdin.buffer.read()
d.decode("utf-8")
sys.exit(1 if any((b < 32 and b not in (9, 10)) or b == 127 for b in d) else 0)'; then
    pass "garbage $format: only printable UTF-8 on the terminal"
  else
    fail "garbage $format: raw bytes reached the terminal"
  fi
done

# Not a regular file: refused at once (a FIFO must not block).
mkdir folder.cfg
expect_rc 2 "a folder as --machine" --machine folder.cfg run 1
text_check "folder named" "folder.cfg: is a directory"
mkfifo fifo.cfg
expect_rc 2 "a FIFO as --machine" --machine fifo.cfg run 1
text_check "FIFO named" "is a FIFO"
expect_rc 0 "the demo cell as a file is fine" --machine "$demo" check 1
finish
