; Peer benchmark for flarekit apply: GIMP 2.10's Lens Flare filter (plug-in-flarefx, after
; Karl-Johan Andersson's FlareFX) on a PNG, headless. Run by bench/peers/compare.sh:
;   gimp-console -i -d -f -b '(begin (load "gimp_lens_flare.scm")
;                                    (flarekit-gimp-flare "IN.png" "OUT.png" X Y))' -b '(gimp-quit 0)'
(define (flarekit-gimp-flare in out x y)
  (let* ((image (car (gimp-file-load RUN-NONINTERACTIVE in in)))
         (drawable (car (gimp-image-get-active-drawable image))))
    (plug-in-flarefx RUN-NONINTERACTIVE image drawable x y)
    ; zlib level 1, as flarekit writes by default (GIMP exports at 9), so both pay the same
    ; encoder and the ratio is the rest of the process.
    (file-png-save2 RUN-NONINTERACTIVE image drawable out out 0 1 0 0 0 0 0 0 0)
    (gimp-image-delete image)))
