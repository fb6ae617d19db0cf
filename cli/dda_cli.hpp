// SPDX-License-Identifier: Apache-2.0
#pragma once

namespace dda::cli {
// The whole `dda` command; returns the process exit status.
int main(int argc, char** argv);
}  // namespace dda::cli
