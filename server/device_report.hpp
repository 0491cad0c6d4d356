// The device a render worker opened, as JSON for GET /v1/device.
#pragma once

#include "renderer/gpu_device.hpp"

#include <nlohmann/json.hpp>

namespace server {

nlohmann::json device_report(const renderer::DeviceReport& report);

}  // namespace server
