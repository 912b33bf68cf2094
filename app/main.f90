program main
   use pecplas_model, only: model_t
   implicit none (type, external)
   type(model_t) :: model
   print *, allocated(model%title)
end program main
