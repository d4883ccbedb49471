// The compiled part of the Python package `vantage` (vantage/_vantage): thin bindings over the
// C++ libraries. vantage/__init__.py wraps them in typed Python functions and results
// (vantage/_results.py).

#include <pybind11/pybind11.h>

#include "crb_command.h"
#include "ident_command.h"
#include "layout_commands.h"
#include "layouts.h"
#include "place_command.h"
#include "pose_commands.h"
#include "results.h"
#include "simulate_command.h"
#include "tre_command.h"

PYBIND11_MODULE(_vantage, module) {
  module.doc() =
      "vantage: how good is a fiducial layout for pose from a single affine image (McInroy, "
      "Erwin & Robertson), and how to make it better.";
  module.attr("__version__") = VANTAGE_VERSION;
  vantage::python::register_errors(module);
  vantage::python::bind_layouts(module);
  vantage::python::bind_layout_commands(module);
  vantage::python::bind_pose_commands(module);
  vantage::python::bind_simulate_command(module);
  vantage::python::bind_crb_command(module);
  vantage::python::bind_tre_command(module);
  vantage::python::bind_ident_command(module);
  vantage::python::bind_place_command(module);
}
