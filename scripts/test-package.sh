#!/usr/bin/env bash
# Installs RayLab's Debian package into a fresh minimal Debian 12 root, as a lab machine
# would get it, and runs it there (issue 36). As root (debootstrap, mount, chroot), with
# the network to this machine's Debian mirror:
#
#   sudo scripts/test-package.sh [BUILD_DIR]        (default: build/ci)
#
# also the CTest test PackageFreshRoot: ctest --test-dir build/ci -C package -L package
#
#  1. cpack -G DEB in BUILD_DIR: raylab_<version>_<arch>.deb (builds what is missing);
#  2. debootstrap --variant=minbase bookworm, from the mirror /etc/apt/sources.list* name;
#  3. in the root (chroot, with /proc, /sys and /dev mounted): apt-get install
#     ./raylab_*.deb, which must pull in everything it needs;
#  4. runs `raylab lesson --list` (the eight installed lessons), `raylab render --out
#     x.png`, `xvfb-run -a raylab lesson .../04-whitted.json --out d` (the handout and its
#     pictures), `python3 -c "import raylab"` (a render from Python), and the desktop
#     entry's Exec line with a lesson file (a double-click) under xvfb-run;
#  5. apt-get remove raylab: every file `dpkg -L raylab` listed is gone, and no file or
#     folder named raylab is left outside /root (the user's own cache) and /tmp.
# Each step's time is printed. RAYLAB_KEEP_ROOT=1 keeps the root for a look afterwards.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(cd "${1:-$here/build/ci}" && pwd)"
if [[ $(id -u) -ne 0 ]]; then
  echo "test-package: needs root (debootstrap, mount, chroot): sudo $0 $*" >&2
  exit 1
fi
for tool in debootstrap cpack chroot; do
  if ! command -v "$tool" >/dev/null; then
    echo "test-package: $tool is missing (sudo apt-get install debootstrap cmake)" >&2
    exit 1
  fi
done

started=$SECONDS
step() { echo "test-package: [$((SECONDS - started)) s] $*"; }
fail() {
  echo "test-package: FAILED: $*" >&2
  exit 1
}

# 1. The package.
step "cpack -G DEB in $build"
(cd "$build" && cpack -G DEB >cpack.log 2>&1) || { cat "$build/cpack.log"; fail "cpack"; }
deb="$(ls -t "$build"/raylab_*.deb | head -1)"
[[ -f "$deb" ]] || fail "cpack made no raylab_*.deb in $build"
step "package: $deb ($(du -h "$deb" | cut -f1)); Depends: $(dpkg-deb -f "$deb" Depends)"

# 2. A fresh root from the machine's own mirror.
mirror="$( (grep -shoE '(URIs:|deb) +https?://[^ ]+' /etc/apt/sources.list /etc/apt/sources.list.d/* ||
  true) | grep -v security | head -1 | awk '{print $2}')"
mirror="${mirror:-http://deb.debian.org/debian}"
root="$(mktemp -d /var/tmp/raylab-package-root.XXXXXX)"
cleanup() {
  for m in dev/pts dev sys proc; do
    mountpoint -q "$root/$m" && umount -l "$root/$m"
  done
  if [[ "${RAYLAB_KEEP_ROOT:-0}" == 1 ]]; then
    echo "test-package: the root is kept in $root"
  else
    rm -rf --one-file-system "$root"
  fi
}
trap cleanup EXIT
step "debootstrap --variant=minbase bookworm $root $mirror"
debootstrap --variant=minbase bookworm "$root" "$mirror" >"$root.debootstrap.log" 2>&1 ||
  { tail -20 "$root.debootstrap.log"; fail "debootstrap"; }
rm -f "$root.debootstrap.log"
security="${mirror%/debian}/debian-security"
cat >"$root/etc/apt/sources.list" <<EOF
deb $mirror bookworm main
deb $mirror bookworm-updates main
deb $security bookworm-security main
EOF
mount -t proc proc "$root/proc"
mount -t sysfs sys "$root/sys"
mount --bind /dev "$root/dev"
mount --bind /dev/pts "$root/dev/pts"
in_root() { chroot "$root" env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin LANG=C.UTF-8 "$@"; }

# 3. The package and what it pulls in.
cp "$deb" "$root/tmp/"
step "apt-get install ./$(basename "$deb") in the fresh root"
in_root apt-get update -qq
in_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
  "/tmp/$(basename "$deb")" >"$build/package-install.log" 2>&1 ||
  { tail -30 "$build/package-install.log"; fail "apt-get install"; }
step "installed: $(in_root dpkg-query -W -f='${Package} ${Version}' raylab), \
$(grep -c '^Setting up' "$build/package-install.log") packages set up"

# 4. As a user would run it.
mkdir -p "$root/tmp/work"
in_sh() { in_root sh -ec "cd /tmp/work; $1"; }
step "raylab lesson --list"
list="$(in_sh 'raylab lesson --list')"
echo "$list"
[[ $(grep -cE '^0[1-9]-' <<<"$list") -eq 9 ]] || fail "raylab lesson --list does not list the 9 lessons"
step "raylab render --out x.png"
in_sh 'raylab render --out x.png && test -s x.png' || fail "raylab render"
step "xvfb-run -a raylab lesson /usr/share/raylab/lessons/04-whitted.json --out d"
in_sh 'xvfb-run -a raylab lesson /usr/share/raylab/lessons/04-whitted.json --out d >lesson.log 2>&1 ||
       { cat lesson.log; exit 1; }; test -s d/lesson.md; ls d/*.png | wc -l' ||
  fail "raylab lesson --out"
step "python3 -c \"import raylab\""
in_sh 'python3 -c "import raylab; print(\"python:\", raylab.__file__, raylab.render(raylab.default_scene(), spp=1).shape)"' ||
  fail "import raylab"
exec_line="$(sed -n 's/^Exec=//p' "$root/usr/share/applications/org.raylab.RayLab.desktop")"
command="${exec_line//%f//usr/share/raylab/lessons/04-whitted.json} --quit-after-ms 3000"
step "the desktop entry's Exec line on a lesson (a double-click): xvfb-run -a $command"
in_sh "xvfb-run -a $command" || fail "the desktop entry's command"

# 5. Removal leaves nothing behind.
in_root dpkg -L raylab | sort >"$root/tmp/raylab.files"
step "apt-get remove raylab ($(wc -l <"$root/tmp/raylab.files") paths listed by dpkg -L)"
in_root env DEBIAN_FRONTEND=noninteractive apt-get remove -y -qq raylab >"$build/package-remove.log" 2>&1 ||
  { cat "$build/package-remove.log"; fail "apt-get remove"; }
grep -i "warning" "$build/package-remove.log" && fail "dpkg warned while removing raylab"
left=()
while read -r path; do
  [[ -e "$root$path" && ! -d "$root$path" ]] && left+=("$path")
done <"$root/tmp/raylab.files"
while read -r path; do
  left+=("${path#"$root"}")
done < <(find "$root" -mindepth 1 -xdev \( -path "$root/tmp" -o -path "$root/root" -o -path "$root/proc" \
  -o -path "$root/var/lib/dpkg" -o -path "$root/var/cache/apt" -o -path "$root/var/log" \) -prune \
  -o -iname '*raylab*' -print)
((${#left[@]} == 0)) || fail "left behind after apt-get remove raylab: ${left[*]}"
step "PASSED: installed, ran and removed without a trace"
