#include "server/device_report.hpp"

#include <cstdio>
#include <string>

namespace server {
namespace {

std::string hex_id(std::uint32_t id) {
  char text[16];
  std::snprintf(text, sizeof(text), "0x%04x", id);
  return text;
}

}  // namespace

nlohmann::json device_report(const renderer::DeviceReport& report) {
  const renderer::DeviceLimits& l = report.limits;
  const nlohmann::json limits = {
      {"max_image_dimension_2d", l.max_image_dimension_2d},
      {"max_image_dimension_3d", l.max_image_dimension_3d},
      {"max_image_array_layers", l.max_image_array_layers},
      {"max_framebuffer_width", l.max_framebuffer_width},
      {"max_framebuffer_height", l.max_framebuffer_height},
      {"max_color_attachments", l.max_color_attachments},
      {"max_uniform_buffer_range", l.max_uniform_buffer_range},
      {"max_storage_buffer_range", l.max_storage_buffer_range},
      {"max_texel_buffer_elements", l.max_texel_buffer_elements},
      {"max_push_constants_size", l.max_push_constants_size},
      {"max_bound_descriptor_sets", l.max_bound_descriptor_sets},
      {"max_compute_shared_memory_size", l.max_compute_shared_memory_size},
      {"max_compute_work_group_invocations", l.max_compute_work_group_invocations},
      {"max_compute_work_group_size", l.max_compute_work_group_size},
      {"max_compute_work_group_count", l.max_compute_work_group_count},
      {"timestamp_compute_and_graphics", l.timestamp_compute_and_graphics},
  };
  const auto& v = report.api_version;
  return {{"name", report.name},
          {"driver", report.driver},
          {"api_version", std::to_string(v[0]) + "." + std::to_string(v[1]) + "." + std::to_string(v[2])},
          {"vendor_id", hex_id(report.vendor_id)},
          {"device_id", hex_id(report.device_id)},
          {"type", report.type},
          {"timestamp_period_ns", report.timestamp_period_ns},
          {"limits", limits}};
}

}  // namespace server
