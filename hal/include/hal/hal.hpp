// hal/hal.hpp: the whole HAL interface in one include.
#pragma once

#include "hal/command_list.hpp"
#include "hal/device.hpp"
#include "hal/error.hpp"
#include "hal/shader.hpp"
#include "hal/types.hpp"
