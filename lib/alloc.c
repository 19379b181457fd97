/* Every byte carom allocates goes through here, so a caller's allocator sees
 * all of it and allocation failure can be injected in one place. */
#include "alloc.h"

#include <stdint.h>
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

/* The elements a block must hold beyond an array's to align it: MEM_LINE - 1
 * bytes reach a line from any address. */
static int32_t lines_extra (size_t elem)
{
  return (int32_t) ((MEM_LINE - 1 + elem - 1) / elem);
}

int32_t mem_lines_usable (int32_t cap, size_t elem)
{
  return cap > lines_extra (elem) ? cap - lines_extra (elem) : 0;
}

int mem_reserve_lines (const carom_allocator *a, void **room, void **array, int32_t *cap, int32_t need, size_t elem)
{
  int32_t extra = lines_extra (elem);
  uintptr_t p;
  /* (as mem_reserve, no block while none is needed) */
  if (need > mem_lines_usable (*cap, elem)
      && (need > INT32_MAX - extra || !mem_reserve (a, room, cap, need + extra, elem)))
    return 0;
  p = (uintptr_t) *room;
  *array = *room ? (char *) *room + ((MEM_LINE - p % MEM_LINE) % MEM_LINE) : NULL;
  return 1;
}
