#!/usr/bin/env bash
# Files are never clobbered (issue 22 §3, docs/decisions/config-files.md):
# compile refuses its own source as output (also under another name), a
# FIFO or folder as output; writes through a symbolic link; md set refuses a
# read-only data file; --programs FILE and odd *.DAT entries are named.
source "$(dirname "$0")/common.bash"
export XDG_STATE_HOME="$TEST_TMP/state"
cd "$TEST_TMP" || exit 1
printf 'N0000 G0 X0 Y0\nN0001 G1 X10 F1000 RD2\nN0002 Y10\nN0003 M30\n' >X.DAT
cp X.DAT original.DAT

expect_rc 2 "compile X.DAT -o X.DAT" compile X.DAT -o X.DAT
text_check "source named" "is the source program itself"
cmp -s X.DAT original.DAT && pass "the source is unchanged" || fail "the source was overwritten"
expect_rc 2 "compile X.DAT -o ./sub/../X.DAT" compile X.DAT -o ./X.DAT
ln -s X.DAT alias.NCO
expect_rc 2 "compile X.DAT -o a link to X.DAT" compile X.DAT -o alias.NCO
cmp -s X.DAT original.DAT && pass "the source is still unchanged" || fail "overwritten via a link"

mkfifo pipe.NCO
expect_rc 2 "compile -o FIFO" compile X.DAT -o pipe.NCO
text_check "FIFO named" "pipe.NCO is a FIFO"
[ -p pipe.NCO ] && pass "the FIFO is still a FIFO" || fail "the FIFO was replaced"
mkdir folder.NCO
expect_rc 2 "compile -o folder" compile X.DAT -o folder.NCO
[ -d folder.NCO ] && pass "the folder is still a folder" || fail "the folder was replaced"

mkdir real
ln -s real/out.NCO link.NCO
echo old >real/out.NCO
expect_rc 0 "compile -o a symbolic link" compile X.DAT -o link.NCO
[ -L link.NCO ] && pass "the link stays a link" || fail "the link was replaced by a file"
grep -q "N0001" real/out.NCO && pass "the real file got the object" || fail "real file: $(cat real/out.NCO)"
printf 'N0001 G1 X10 F1000 RD2\nN0002 M30\n' >bad.DAT
expect_rc 1 "a compile with errors -o the link" compile bad.DAT -o link.NCO
[ -L link.NCO ] && [ ! -e real/out.NCO ] && pass "the link stays, its stale object is gone" \
  || fail "link or object: $(ls -l link.NCO real)"
expect_rc 0 "the next compile writes through the link again" compile X.DAT -o link.NCO
grep -q "N0001" real/out.NCO && pass "the object is back in the real file" || fail "no object"

data="$TEST_TMP/readonly.mdt"
expect_rc 0 "md set makes a data file" --data "$data" md set 60 5 7
chmod 0444 "$data"
cp "$data" before.mdt
expect_rc 2 "md set on a read-only data file" --data "$data" md set 60 5 8
text_check "read-only named" "read-only"
cmp -s "$data" before.mdt && pass "the read-only file is unchanged" || fail "the read-only file changed"

echo "not a folder" >programs.txt
expect_rc 2 "--programs FILE" --programs programs.txt check 1
text_check "--programs FILE says what is wrong" "is a file, not a program directory"
expect_rc 2 "--programs missing" --programs nowhere check 1
text_check "--programs missing says so" "does not exist"
mkdir progs progs/N1010005.DAT
cp "$MTC_SOURCE_DIR/resources/programs/N1010001.DAT" "$MTC_SOURCE_DIR/resources/programs/N1010099.DAT" progs/
expect_rc 0 "a folder named *.DAT in the program directory" --programs progs check 1
text_check "the folder is reported" "N1010005.DAT is a directory"
finish
