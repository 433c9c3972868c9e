#!/usr/bin/env bash
# Rewrites include/granbond.h from the Rust sources (the header test compares
# against the same generation, so a stale header fails `cargo test`).
set -euo pipefail
cd "$(dirname "$0")"
GRANBOND_BLESS=1 cargo test -q --test header
