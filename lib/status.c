/* Status strings and the run-time version. */
#include "carom.h"

uint32_t carom_version (void)
{
  return CAROM_VERSION;
}

const char *carom_status_string (carom_status status)
{
  switch (status)
    {
    case CAROM_OK: return "ok";
    case CAROM_ERR_NULL_ARGUMENT: return "a required pointer argument is NULL";
    case CAROM_ERR_NOT_FINITE: return "a number is NaN or infinite";
    case CAROM_ERR_BAD_SIZE: return "a size is zero, negative or outside [1e-60, 1e60]";
    case CAROM_ERR_BAD_DENSITY: return "density must be positive and give a mass in [1e-200, 1e200]";
    case CAROM_ERR_TOO_FEW_VERTICES: return "a polygon needs at least 3 vertices";
    case CAROM_ERR_TOO_MANY_VERTICES: return "too many vertices (limit CAROM_MAX_POLYGON_VERTICES)";
    case CAROM_ERR_REPEATED_VERTEX: return "two consecutive vertices coincide";
    case CAROM_ERR_SELF_INTERSECTING: return "the polygon's edges cross or touch each other";
    case CAROM_ERR_ZERO_AREA: return "the polygon has (nearly) zero area";
    case CAROM_ERR_BAD_TIME_STEP: return "the time step must be positive and finite";
    case CAROM_ERR_STALE_BODY: return "the body id is unknown or the body was removed";
    case CAROM_ERR_OUT_OF_MEMORY: return "out of memory";
    case CAROM_ERR_BAD_ARGUMENT: return "an argument is outside its documented range";
    case CAROM_ERR_BAD_STRUCT_SIZE: return "the struct's size field is not one this library knows";
    case CAROM_ERR_TOO_MANY_BODIES: return "the world holds the maximum number of bodies";
    case CAROM_ERR_STATIC_BODY: return "the call needs a dynamic body";
    case CAROM_ERR_SCENE_SYNTAX: return "a scene line is malformed";
    case CAROM_ERR_IO: return "a file could not be read";
    case CAROM_ERR_STALE_JOINT: return "the joint id is unknown or the joint was removed";
    case CAROM_STATUS_FORCE_32: break;
    }
  return "unknown status";
}
