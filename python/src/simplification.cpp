// Copyright (c) 2026 The PR-star octree project.
// SPDX-License-Identifier: LGPL-3.0-or-later

#include "prstar_python.h"

namespace prstar_python {

void bind_simplification(py::module_&) {}

} // namespace prstar_python
