/* Every byte carom allocates goes through here, so a caller's allocator sees
 * all of it and allocation failure can be injected in one place. */
#include "alloc.h"

#include <stdlib.h>
#include <string.h>

void *mem_alloc (const carom_allocator *a, size_t size)
{
  if (size == 0)
    size = 1;
  if (a->alloc)
    return a->alloc (size, a->user);
  return malloc (size);
}

void mem_free (const carom_allocator *a, void *ptr, size_t size)
{
  if (!ptr)
    return;
  if (a->alloc)
    {
      if (a->free)
        a->free (ptr, size == 0 ? 1 : size, a->user);
      return;
    }
  free (ptr);
}

void *mem_realloc (const carom_allocator *a, void *ptr, size_t old_size, size_t new_size)
{
  void *p = mem_alloc (a, new_size);
  if (!p)
    return NULL;
  if (ptr)
    {
      memcpy (p, ptr, old_size < new_size ? old_size : new_size);
      mem_free (a, ptr, old_size);
    }
  return p;
}

int mem_reserve (const carom_allocator *a, void **array, int32_t *cap, int32_t need, size_t elem)
{
  int32_t new_cap;
  void *p;
  if (need <= *cap)
    return 1;
  new_cap = *cap < 16 ? 16 : *cap;
  while (new_cap < need)
    {
      if (new_cap > INT32_MAX / 2)
        return 0;
      new_cap *= 2;
    }
  p = mem_realloc (a, *array, (size_t) *cap * elem, (size_t) new_cap * elem);
  if (!p)
    return 0;
  *array = p;
  *cap = new_cap;
  return 1;
}
