!> Writes or checks the generated variable tables of docs/input/<group>.md (landyn_input_docs).
!! Usage: landyn_input_docs_tool --check DIR | --write DIR. --check exits 1 when a page is not
!! current (run the tool with --write, or `cmake --build <build> --target input_docs`).
program landyn_input_docs_tool
  use landyn_status, only: status_t, EXIT_USAGE, EXIT_DIVERGED, EXIT_FILE
  use landyn_files, only: read_whole_file
  use landyn_input_registry, only: n_groups, group_names
  use landyn_input_docs, only: replace_table
  implicit none
  character(len=4096) :: mode, dir
  character(len=:), allocatable :: path, page, new_page
  type(status_t) :: st
  integer :: ig, u, n_stale
  logical :: ok
  if (command_argument_count() /= 2) then
    write (*, '(a)') 'usage: landyn_input_docs_tool --check DIR | --write DIR'
    stop EXIT_USAGE
  end if
  call get_command_argument(1, mode)
  call get_command_argument(2, dir)
  n_stale = 0
  do ig = 1, n_groups
    path = trim(dir)//'/'//trim(group_names(ig))//'.md'
    call read_whole_file(path, page, st)
    if (.not. st%ok()) then
      write (*, '(a)') path//': cannot read: '//st%text()
      stop EXIT_FILE
    end if
    call replace_table(page, ig, new_page, ok)
    if (.not. ok) then
      write (*, '(a)') path//': no variable table and no generated-table markers'
      stop EXIT_FILE
    end if
    if (new_page == page .and. len(new_page) == len(page)) cycle
    n_stale = n_stale + 1
    if (trim(mode) == '--write') then
      open (newunit=u, file=path, access='stream', form='unformatted', status='replace')
      write (u) new_page
      close (u)
      write (*, '(a)') 'updated '//path
    else
      write (*, '(a)') path//': the variable table is not current; run landyn_input_docs_tool --write '//trim(dir)
    end if
  end do
  if (trim(mode) /= '--write' .and. n_stale > 0) stop EXIT_DIVERGED   ! "a comparison failed"

end program landyn_input_docs_tool
