/* The world's allocator: the caller's carom_allocator or malloc/free. */
#ifndef CAROM_ALLOC_H
#define CAROM_ALLOC_H

#include "carom.h"

void *mem_alloc (const carom_allocator *a, size_t size);
void mem_free (const carom_allocator *a, void *ptr, size_t size);
/* Grow or shrink a block, keeping min(old, new) bytes; NULL on failure, and
 * then the old block is untouched. */
void *mem_realloc (const carom_allocator *a, void *ptr, size_t old_size, size_t new_size);

/* Make room for at least `need` elements of `elem` bytes in *array, whose
 * capacity is *cap; grows geometrically. Returns 0 on failure (nothing
 * changed), 1 on success. */
int mem_reserve (const carom_allocator *a, void **array, int32_t *cap, int32_t need, size_t elem);

/* The same for an array whose first element must start on a multiple of
 * MEM_LINE bytes (a cache line): *room is the block allocated, *array
 * where the elements begin within it, and *cap counts the room's elements,
 * of which mem_lines_usable (*cap, elem) are the array's (the rest may go
 * to the alignment). The elements are not kept when it grows. Free *room,
 * *cap elements. */
#define MEM_LINE 64
int mem_reserve_lines (const carom_allocator *a, void **room, void **array, int32_t *cap, int32_t need, size_t elem);
int32_t mem_lines_usable (int32_t cap, size_t elem);

#endif
