#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 GrazeLab developers
# Re-checks the README's claim that its commands work on a Debian 12 root with nothing
# preinstalled: builds such a root (debootstrap --variant=minbase bookworm), copies this
# repository (its tracked and untracked, not ignored, files as they are on disk: no build, no
# .git) and ../shared into it, and runs `bash .ci/run` inside as root with CI=true, as CI does.
# Run it before changing that sentence, and whenever set-up, install or packaging changes.
#
# usage (as root): bash tools/check-fresh-debian.sh [ROOT]      ROOT: /var/tmp/grazelab-fresh-debian
#   GRAZELAB_DEBIAN_MIRROR   the archive debootstrap reads (http://deb.debian.org/debian)
#   GRAZELAB_FRESH_COMMAND   what runs in the root instead of `bash .ci/run` (e.g. the explorer's
#                            command: "bash tools/run-explorer.sh --help")
# The root is made anew on every run; its log is ROOT.log. Exit status: the command's.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
shared=$(cd "$repo/../shared" 2>/dev/null && pwd) || { echo "no ../shared beside the repository" >&2; exit 2; }
root=${1:-/var/tmp/grazelab-fresh-debian}
mirror=${GRAZELAB_DEBIAN_MIRROR:-http://deb.debian.org/debian}
command=${GRAZELAB_FRESH_COMMAND:-bash .ci/run}

[ "$(id -u)" -eq 0 ] || { echo "debootstrap and chroot need root" >&2; exit 2; }
case "$root" in /|/usr|/var|/tmp|/work|"$repo"*) echo "refusing to use $root as the root" >&2; exit 2 ;; esac
if ! command -v debootstrap > /dev/null; then
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap
fi

# A bound /dev under a folder about to be removed would be emptied with it: never remove a
# root while anything is mounted inside it.
unmount_all() {
  local point
  for point in $(findmnt -rn -o TARGET | grep -F "$root/" | sort -r); do
    umount -l "$point" || true
  done
}
trap unmount_all EXIT
unmount_all
if findmnt -rn -o TARGET | grep -qF "$root/"; then
  echo "something is still mounted under $root: not removing it" >&2; exit 2
fi
rm -rf --one-file-system "$root"

echo "debootstrap --variant=minbase bookworm $root ($mirror)"
debootstrap --variant=minbase bookworm "$root" "$mirror" > "$root.log" 2>&1 \
  || { tail -20 "$root.log"; echo "debootstrap failed" >&2; exit 2; }
cp /etc/resolv.conf "$root/etc/resolv.conf"

mkdir -p "$root/work/main" "$root/work/shared"
git -C "$repo" ls-files -z --cached --others --exclude-standard \
  | (cd "$repo" && xargs -0 tar --no-recursion -cf - --ignore-failed-read) | tar -xf - -C "$root/work/main"
cp -a "$shared/." "$root/work/shared/"

mount -t proc proc "$root/proc"
mount --rbind /dev "$root/dev" && mount --make-rslave "$root/dev"
mount -t sysfs sysfs "$root/sys"

echo "in the root: $command (log: $root.log)"
start=$(date +%s)
set +e
chroot "$root" /usr/bin/env -i HOME=/root TERM=dumb CI=true \
  PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
  bash -c "cd /work/main && $command" >> "$root.log" 2>&1
status=$?
set -e
tail -40 "$root.log"
echo "fresh Debian 12 root: '$command' exited $status after $(( $(date +%s) - start )) s"
exit "$status"
