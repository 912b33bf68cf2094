!> Copies the deck line of every node, element and joint into model%provenance once the
!> model is built, so that checks after reading can cite "file:line".
module pecplas_io_deck_record_places
   use pecplas_io_text_fields, only: same_name
   use pecplas_io_deck_state, only: deck_state_t
   use pecplas_model_type, only: model_t
   use pecplas_model_provenance, only: place_t
   implicit none (type, external)
   private

   public :: record_places

contains

   subroutine record_places(state, model)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      integer :: i, s, k, e, nel, n0
      type(place_t), allocatable :: split(:)
      integer, allocatable :: fmap(:)
      ! provenance file index of each file of the line store, found on first use
      allocate (fmap(size(state%lines%files)))
      fmap = 0
      associate (pv => model%provenance)
         allocate (pv%nodes(size(state%mesh_node_at)))
         do i = 1, size(state%mesh_node_at)
            pv%nodes(i) = here(state, model, fmap, state%mesh_node_at(i))
         end do
         allocate (pv%esets(size(model%mesh%esets)))
         do s = 1, size(model%mesh%esets)
            nel = size(model%mesh%esets(s)%conn, 2)
            allocate (pv%esets(s)%at(nel))
            k = 0
            if (allocated(state%esets)) then
               do k = size(state%esets), 1, -1
                  if (same_name(state%esets(k)%name, model%mesh%esets(s)%name)) exit
               end do
            end if
            if (k > 0) then
               pv%esets(s)%keyword = '*ELEMENTS'
               do e = 1, min(nel, state%esets(k)%n)
                  pv%esets(s)%at(e) = here(state, model, fmap, state%esets(k)%where(e))
               end do
            else if (s <= size(state%mesh_eset_at)) then
               pv%esets(s)%keyword = '*MESH'
               pv%esets(s)%at = here(state, model, fmap, state%mesh_eset_at(s))
            else
               pv%esets(s)%keyword = ''
            end if
         end do
         if (.not. allocated(model%joint_sets)) return
         allocate (pv%joint_sets(size(model%joint_sets)))
         n0 = size(pv%nodes)
         do s = 1, size(model%joint_sets)
            nel = size(model%joint_sets(s)%conn, 2)
            allocate (pv%joint_sets(s)%at(nel))
            pv%joint_sets(s)%keyword = '*JOINTS'
            if (.not. allocated(state%joint_sets)) cycle
            if (s > size(state%joint_sets)) cycle
            associate (raw => state%joint_sets(s))
               if (raw%n > 0) then
                  do e = 1, min(nel, raw%n)
                     pv%joint_sets(s)%at(e) = here(state, model, fmap, raw%where(e))
                  end do
               else
                  pv%joint_sets(s)%at = here(state, model, fmap, raw%at)
               end if
            end associate
         end do
         ! nodes split for generated joints (after the deck's nodes): the joint's line
         if (model%mesh%nnode() > n0) then
            allocate (split(model%mesh%nnode()))
            split(1:n0) = pv%nodes
            do s = 1, size(model%joint_sets)
               do e = 1, size(model%joint_sets(s)%conn, 2)
                  do i = 1, size(model%joint_sets(s)%conn, 1)
                     k = model%joint_sets(s)%conn(i, e)
                     if (k > n0 .and. k <= size(split)) then
                        if (split(k)%line == 0) split(k) = pv%joint_sets(s)%at(e)
                     end if
                  end do
               end do
            end do
            call move_alloc(split, pv%nodes)
         end if
      end associate
   end subroutine record_places

   !> Place of deck line index `at` (unknown when 0); fmap(f): provenance file index of
   !> line-store file f (0 until its first use).
   function here(state, model, fmap, at) result(p)
      type(deck_state_t), intent(in) :: state
      type(model_t), intent(inout) :: model
      integer, intent(inout) :: fmap(:)
      integer, intent(in) :: at
      type(place_t) :: p
      integer :: f
      if (at < 1 .or. at > state%lines%n) return
      ! names from the line store's tables: no temporary per node
      associate (ln => state%lines)
         f = ln%file_of(at)
         if (fmap(f) == 0) then
            p = model%provenance%place(ln%files(f)%s, ln%num(at))
            fmap(f) = p%file
         else
            p%file = fmap(f)
            p%line = ln%num(at)
         end if
         if (ln%kw_of(at) == 0) then
            p%keyword = ''
         else
            p%keyword = ln%keywords(ln%kw_of(at))%s
         end if
      end associate
   end function here

end module pecplas_io_deck_record_places
