#!/usr/bin/env bash
# `cpack -G DEB` of a strata build, then the package checked as apt would install it: its name
# and fields, dpkg-shlibdeps' dependencies against what the executable loads, its contents
# extracted with dpkg-deb -x (executable, headers, CMake package, man page), ldd of the
# executable, and the extracted executable run: --version, a slice of data/ring.stl read back.
# Usage: build_and_check_deb.sh BUILD_DIR SOURCE_DIR SCRATCH_DIR VERSION LIBDIR
#   VERSION  the project's version; LIBDIR  the build's CMAKE_INSTALL_LIBDIR
# Environment: CPACK, the cpack of the build (default: cpack on the PATH).
set -euo pipefail
cpack=${CPACK:-cpack}
build=$1 source=$2 scratch=$3 version=$4 libdir=$5
root=$scratch/root
rm -rf "$scratch"
mkdir -p "$scratch"

echo "== cpack -G DEB"
# zstd instead of the package's xz: the same contents, packed in a few seconds rather than
# minutes (the sanitizer build's archive and executable are large).
"$cpack" -G DEB --config "$build/CPackConfig.cmake" -B "$scratch/cpack" \
  -D CPACK_DEBIAN_COMPRESSION_TYPE=zstd > "$scratch/cpack.log" \
  || { cat "$scratch/cpack.log"; exit 1; }
deb=$scratch/cpack/strata_${version}_amd64.deb
[ -f "$deb" ] || { echo "no $deb"; ls "$scratch/cpack"; exit 1; }
ls -l "$deb"
dpkg-deb --field "$deb"
[ "$(dpkg-deb --field "$deb" Package)" = strata ]
[ "$(dpkg-deb --field "$deb" Version)" = "$version" ]
[ "$(dpkg-deb --field "$deb" Architecture)" = amd64 ]

echo "== contents"
dpkg-deb -x "$deb" "$root"
cmakedir=usr/$libdir/cmake/strata
for file in usr/bin/strata usr/include/strata/strata.hpp "usr/$libdir/libstrata.a" \
  "$cmakedir/strataConfig.cmake" "$cmakedir/strataConfigVersion.cmake" \
  "$cmakedir/strataTargets.cmake" usr/share/man/man1/strata.1.gz \
  usr/share/doc/strata/README.md usr/share/doc/strata/library.md; do
  [ -f "$root/$file" ] || { echo "not in the package: $file"; exit 1; }
done
# The man page is help2man's: the title line, and the commands of strata --help.
zcat "$root/usr/share/man/man1/strata.1.gz" > "$scratch/strata.1"
grep -q '^\.TH STRATA "1"' "$scratch/strata.1"
for command in slice info check validate view serve; do
  grep -q "^$command\b" "$scratch/strata.1" || { echo "strata.1 misses $command"; exit 1; }
done

echo "== ldd and the package's dependencies"
ldd "$root/usr/bin/strata" | tee "$scratch/ldd.txt"
if grep -q 'not found' "$scratch/ldd.txt"; then exit 1; fi
# The package names of Depends, one a line, without versions.
depends=$(dpkg-deb --field "$deb" Depends | tr ',' '\n' | sed 's/^ *//; s/[ (].*//')
# What installing the .deb brings in: Depends and, as installed here, what those depend on (a
# library's own libraries, e.g. lib3mf1's libuuid1, are its package's dependencies, not ours).
closure=$depends
mapfile -t queue <<< "$depends"
while ((${#queue[@]})); do
  next=${queue[0]}
  queue=("${queue[@]:1}")
  for dependency in $(dpkg-query -W -f='${Depends},${Pre-Depends}\n' "$next" 2>/dev/null \
    | tr ',|' '\n' | sed 's/^ *//; s/[ (:].*//' | grep -v '^$'); do
    grep -qxF "$dependency" <<< "$closure" || { closure+=$'\n'"$dependency"; queue+=("$dependency"); }
  done
done
# Every shared library the executable loads must come from a package that installing it brings.
for library in $(awk '$2 == "=>" { print $3 }' "$scratch/ldd.txt"); do
  owner=$(dpkg -S "$library" 2>/dev/null || dpkg -S "${library#/usr}" 2>/dev/null \
    || dpkg -S "/usr$library" 2>/dev/null) || { echo "no package owns $library"; exit 1; }
  package=${owner%%:*}
  grep -qxF "$package" <<< "$closure" \
    || { echo "$library comes from $package, which neither Depends nor its dependencies name"; exit 1; }
done

echo "== the packaged executable"
strata=$root/usr/bin/strata
[ "$("$strata" --version)" = "strata $version" ] || { "$strata" --version; exit 1; }
"$strata" slice "$source/data/ring.stl" --cell 0.5 --layer 0.5 --format cells,json \
  -o "$scratch/out" > "$scratch/slice.log"
"$strata" info "$scratch/out/ring.cells" | tee "$scratch/info.txt"
# The cells file read back holds the counts the slice reported, and solid cells of both classes.
count() {
  sed -n "/^  \"cells\": {/,/^  }/s/^ *\"$1\": \([0-9]*\),*$/\1/p" "$scratch/out/ring.json"
}
reported="cells    $(count empty) empty (00), $(count interior) interior (01),"
reported+=" $(count boundary) boundary (11)"
grep -qxF "$reported" "$scratch/info.txt" || { echo "the report says: $reported"; exit 1; }
[ "$(count interior)" -gt 0 ] && [ "$(count boundary)" -gt 0 ]
