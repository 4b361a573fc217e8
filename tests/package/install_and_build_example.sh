#!/usr/bin/env bash
# `cmake --install` of a strata build into a scratch prefix, then examples/ configured and built
# against that prefix alone (find_package(strata)) and run on data/ring.stl. Checks what was
# installed, that the public headers include no CGAL, GMP, MPFR or Boost header, and that the
# example's cells file is byte for byte the one the installed strata executable writes.
# Usage: install_and_build_example.sh BUILD_DIR SOURCE_DIR SCRATCH_DIR LIBDIR CXX [CMAKE_ARGS...]
#   LIBDIR      the build's CMAKE_INSTALL_LIBDIR
#   CXX         the compiler of the build, which compiles the header check
#   CMAKE_ARGS  configure the example (generator, compiler and flags of the build under test)
# Environment: CMAKE, the cmake of the build (default: cmake on the PATH).
set -euo pipefail
cmake=${CMAKE:-cmake}
build=$1 source=$2 scratch=$3 libdir=$4 cxx=$5
shift 5
prefix=$scratch/prefix
rm -rf "$scratch"
mkdir -p "$scratch"

echo "== cmake --install $build --prefix $prefix"
"$cmake" --install "$build" --prefix "$prefix" > "$scratch/install.log"
for file in bin/strata "$libdir/libstrata.a" include/strata/strata.hpp \
  include/strata/io/read_cells.hpp "$libdir/cmake/strata/strataConfig.cmake" \
  "$libdir/cmake/strata/strataConfigVersion.cmake" "$libdir/cmake/strata/strataTargets.cmake" \
  share/man/man1/strata.1.gz share/doc/strata/README.md share/doc/strata/library.md \
  share/doc/strata/examples/CMakeLists.txt; do
  [ -f "$prefix/$file" ] || { echo "not installed: $file"; exit 1; }
done
installed_headers=$(cd "$prefix/include" && find strata -name '*.hpp' | sort)
source_headers=$(cd "$source/include" && find strata -name '*.hpp' | sort)
[ "$installed_headers" = "$source_headers" ] \
  || { echo "the installed headers are not those of include/"; exit 1; }

echo "== the public headers, all in one unit, from the installed tree alone"
sed 's/.*/#include "&"/' <<< "$installed_headers" > "$scratch/all_headers.cpp"
"$cxx" -std=c++20 -fsyntax-only -H -I "$prefix/include" "$scratch/all_headers.cpp" \
  2> "$scratch/headers.log" || { cat "$scratch/headers.log"; exit 1; }
# -H lists every header read, one a line after dots for the depth.
if grep -E '/(CGAL|boost)/|/(gmp|gmpxx|mpfr)\.h' "$scratch/headers.log"; then
  echo "a public header includes CGAL, Boost, GMP or MPFR"
  exit 1
fi
if grep -E '/strata/' "$scratch/headers.log" | grep -v -F "$prefix/include/strata/"; then
  echo "a public header includes a strata header from outside the installed tree"
  exit 1
fi
echo "$(grep -c -F "$prefix/include/strata/" "$scratch/headers.log") strata headers read," \
  "none includes CGAL, Boost, GMP or MPFR"

echo "== examples/ against $prefix"
"$cmake" -S "$source/examples" -B "$scratch/example" -DCMAKE_PREFIX_PATH="$prefix" "$@" \
  > "$scratch/example-configure.log" || { cat "$scratch/example-configure.log"; exit 1; }
found=$(sed -n 's/^strata_DIR:PATH=//p' "$scratch/example/CMakeCache.txt")
[ "$found" = "$prefix/$libdir/cmake/strata" ] || { echo "found strata in '$found'"; exit 1; }
"$cmake" --build "$scratch/example" > "$scratch/example-build.log" \
  || { cat "$scratch/example-build.log"; exit 1; }
"$scratch/example/slice_and_count" "$source/data/ring.stl" "$scratch/ring.cells" 0.5 \
  | tee "$scratch/example.out"
grep -q '^ok: the cells file holds the slice$' "$scratch/example.out"
# data/ring.stl is closed: at 0.5 mm it has interior and boundary cells, read back as sliced.
read -r interior boundary < <(sed -n \
  's/^read back: [0-9]* empty, \([0-9]*\) interior, \([0-9]*\) boundary$/\1 \2/p' \
  "$scratch/example.out")
[ "${interior:-0}" -gt 0 ] && [ "${boundary:-0}" -gt 0 ] || { echo "no solid cells"; exit 1; }

echo "== the installed strata executable on the same slice"
"$prefix/bin/strata" slice "$source/data/ring.stl" --cell 0.5 --layer 0.5 --format cells \
  -o "$scratch/cli" > "$scratch/cli.log"
cmp "$scratch/ring.cells" "$scratch/cli/ring.cells"
echo "the example's cells file equals strata slice's"
