#pragma once
// The sensors rangesim ships, in thesis order: the one place a sensor is registered.
//
// Each sensor is a folder in every level (core/<s>/, golden/<s>/, systemc/<s>/, rtl/<s>/, tb/<s>/,
// tests/.../<s>/) that defines that level's part of the sensor interface (ARCHITECTURE.md, "The
// sensor interface"); each level expands this list to build its own table, so no code outside
// the registries names a sensor. Adding a sensor: its folders, then one line here.
#define RANGESIM_FOR_EACH_SENSOR(X) \
  X(ls_conventional)                \
  X(ls_demodulation)                \
  X(tof_lockin)                     \
  X(tof_spad)
